#include "score_report.hpp"

#include <iomanip>
#include <sstream>
#include <string>

namespace scanfilter::cli {

namespace {
// A share of nothing is no score: "n/a", not the 1.0 the ratios take for 0/0.
std::string shareOrNa(double share, std::size_t of) {
  if (of == 0) return "n/a";
  std::ostringstream text;
  text << std::fixed << std::setprecision(4) << share;
  return text.str();
}

void printClass(std::ostream& out, const char* name, const RemovalClassScore& s) {
  // F1 needs a recall: none without truth. With truth and nothing removed it
  // is 0 (recall 0), as the ratios give it.
  out << "  " << std::left << std::setw(13) << name << std::right << std::setw(9) << s.truth << std::setw(10)
      << shareOrNa(s.precision(), s.labelled) << std::setw(10) << shareOrNa(s.recall(), s.truth) << std::setw(10)
      << shareOrNa(s.f1(), s.truth) << "\n";
}

constexpr int kCauseColumn = 31;  // characters: "displaced at grazing incidence" and a space

// What the simulator says made each artefact, and the share of each removed.
void printRecallByCause(std::ostream& out, const RemovalScore& score) {
  bool any = false;
  for (ArtefactCause cause : kEveryArtefactCause) any = any || score.causeTruth(cause) > 0;
  if (!any) return;
  out << "recall by cause (simulator truth):\n";
  out << "  " << std::left << std::setw(kCauseColumn) << "cause" << std::right << std::setw(9) << "truth" << std::setw(10)
      << "recall" << "\n";
  for (ArtefactCause cause : kEveryArtefactCause) {
    if (score.causeTruth(cause) == 0) continue;
    out << "  " << std::left << std::setw(kCauseColumn) << artefactCauseName(cause) << std::right << std::setw(9)
        << score.causeTruth(cause) << std::setw(10) << score.causeRecall(cause) << "\n";
  }
}

}  // namespace

void printScoreReport(std::ostream& out, const RemovalScore& score) {
  out << std::fixed << std::setprecision(4);
  out << "scans: " << score.frames() << "\n";
  out << "labels:";
  for (int c = 0; c < kPointCodeCount; ++c) {
    const auto code = static_cast<PointCode>(c);
    out << "  " << pointCodeName(code) << "=" << score.labelCount(code);
  }
  out << "\n";
  if (!score.hasTruth()) return;
  out << "removal vs truth:\n";
  out << "  class            truth precision    recall        F1\n";
  printClass(out, "jump", score.jump());
  printClass(out, "misdetected", score.misdetected());
  out << "  valid points falsely deleted: " << score.validDeleted() << " of " << score.validTruth() << " ("
      << 100.0 * score.falseDeletionRate() << " %)\n";
  out << "  thin-leg points kept:         " << score.thinLegKept() << " of " << score.thinLegTruth() << " ("
      << 100.0 * score.thinLegRetention() << " %)\n";
  printRecallByCause(out, score);
}

}  // namespace scanfilter::cli
