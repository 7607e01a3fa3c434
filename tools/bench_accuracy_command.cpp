// `scanfilter bench-accuracy`: our filter against the baselines on labelled
// logs, with equal tuning budgets, as markdown tables and PNG figures.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "table_numbers.hpp"
#include "scanfilter/accuracy/comparison_families.hpp"
#include "scanfilter/accuracy/family_tuning.hpp"
#include "scanfilter/accuracy/labelled_logs.hpp"
#include "scanfilter/grouped_bar_chart.hpp"
#include "scanfilter/input_error.hpp"
#include "scanfilter/precision_recall_chart.hpp"
#include "scanfilter/scan_renderer.hpp"
#include "scanfilter/scan_source.hpp"

namespace scanfilter::cli {

namespace {

using accuracy::ParamValues;
using accuracy::SceneVariant;
using accuracy::ScoredFilter;
using accuracy::TunedFamily;

constexpr int kFigureFrames = 6;       // consecutive scans drawn per filter in the frames figure
constexpr int kFigurePanelPixels = 420;

using Logs = std::vector<sim::LabelledLog>;

// The unchanged scenes log odometry with the scenes' own drift
// (sim::kDefaultOdometryDrift); one variant logs the true poses instead.
constexpr sim::OdometryDrift kNoDrift{};

// The scenes as they are, seen by the chosen sensor (empty: their own).
SceneVariant unchangedScenes(const std::string& sensor) {
  SceneVariant variant;
  variant.name = "unchanged scenes";
  variant.sensor = sensor;
  return variant;
}

sim::LabelledLog readLabelledLog(const std::string& path) {
  auto source = openScanSource(path);
  sim::LabelledLog log{std::filesystem::path(path).filename().string(), source->header().sensor, {}};
  ScanRecord record;
  while (source->next(record)) {
    if (record.scan.truth.empty())
      throw InputError(path, record.line, "truth",
                       "missing; bench-accuracy needs labelled logs (scanfilter simulate writes them)");
    log.scans.push_back(std::move(record.scan));
  }
  return log;
}

std::string prf(const RemovalScore& s, const RemovalClassScore& c) {
  return fmt("%.3f", s.removalPrecision(c)) + " / " + fmt("%.3f", c.recall()) + " / **" + fmt("%.3f", s.removalF1(c)) + "**";
}

void comparisonTable(std::ostream& out, const std::vector<TunedFamily>& tuned, const std::vector<ScoredFilter>& as_default,
                     const std::vector<ScoredFilter>& as_tuned) {
  out << "| filter | parameters | jump P / R / F1 | misdetected P / R / F1 | artefacts F1 | valid deleted: all | "
         "0.15-2 m | 2-4 m | 4-6 m | thin legs kept | µs / scan |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (std::size_t f = 0; f < tuned.size(); ++f) {
    for (int variant = 0; variant < 2; ++variant) {
      const ScoredFilter& r = variant == 0 ? as_default[f] : as_tuned[f];
      const ParamValues& values = variant == 0 ? tuned[f].defaults : tuned[f].tuned;
      const RemovalScore& s = r.score;
      out << "| " << tuned[f].family->name << (variant == 0 ? " (default)" : " (tuned)") << " | `"
          << accuracy::describe(*tuned[f].family, values) << "` | " << prf(s, s.jump()) << " | "
          << prf(s, s.misdetected()) << " | " << fmt("%.3f", s.artefactF1()) << " | " << pct(s.falseDeletionRate());
      for (std::size_t b = 0; b < kRangeBandCount; ++b) out << " | " << pct(s.falseDeletionRate(b));
      out << " | " << fmt("%.1f %%", 100.0 * s.thinLegRetention()) << " | " << fmt("%.0f", r.micros_per_scan) << " |\n";
    }
  }
}

// Recall per artefact cause (simulator truth): which filter finds which kind.
void causeTable(std::ostream& out, const std::vector<TunedFamily>& tuned, const std::vector<ScoredFilter>& scored) {
  // Recall alone flatters a filter that deletes everything: the valid
  // returns it deleted stand beside it.
  out << "| filter (tuned): recall by cause |";
  for (ArtefactCause cause : kEveryArtefactCause) out << " " << artefactCauseName(cause) << " |";
  out << " valid deleted |\n|---|";
  for (std::size_t c = 0; c < kEveryArtefactCause.size(); ++c) out << "---|";
  out << "---|\n";
  for (std::size_t f = 0; f < tuned.size(); ++f) {
    const RemovalScore& s = scored[f].score;
    out << "| " << tuned[f].family->name << " |";
    for (ArtefactCause cause : kEveryArtefactCause)
      out << " " << (s.causeTruth(cause) ? fmt("%.3f", s.causeRecall(cause)) : std::string("-")) << " |";
    out << " " << pct(s.falseDeletionRate()) << " |\n";
  }
}

void causeChart(const std::string& path, const std::vector<TunedFamily>& tuned, const std::vector<ScoredFilter>& scored) {
  std::vector<std::string> causes;
  for (ArtefactCause cause : kEveryArtefactCause) causes.emplace_back(artefactCauseName(cause));
  GroupedBarChart chart("Recall by cause of artefact (tuned)", causes);
  for (std::size_t f = 0; f < tuned.size(); ++f) {
    const RemovalScore& s = scored[f].score;
    std::vector<double> recall;
    for (ArtefactCause cause : kEveryArtefactCause)
      recall.push_back(s.causeTruth(cause) ? s.causeRecall(cause) : std::nan(""));  // NaN: no bar
    const std::string valid_deleted = pct(s.falseDeletionRate()) + " valid deleted";
    chart.addSeries(tuned[f].family->name + ": " + valid_deleted, std::move(recall), seriesColour(f));
  }
  chart.draw().save(path);
}

void prChart(const std::string& path, const std::string& title, const std::vector<TunedFamily>& tuned,
             const std::vector<ScoredFilter>& scored, bool jump) {
  PrecisionRecallChart chart(title);
  for (std::size_t f = 0; f < tuned.size(); ++f) {
    const RemovalScore& s = scored[f].score;
    const RemovalClassScore& c = jump ? s.jump() : s.misdetected();
    chart.add(tuned[f].family->name, s.removalPrecision(c), c.recall(), seriesColour(f));
  }
  chart.draw().save(path);
}

// The window of `frames` scans showing most of both artefact kinds:
// ranked by the rarer kind's count in the truth, then by the total.
std::size_t busiestWindow(const sim::LabelledLog& log, std::size_t frames) {
  const auto count = [](const Scan& scan, PointCode c) {
    return static_cast<std::size_t>(std::count(scan.truth.begin(), scan.truth.end(), static_cast<std::uint8_t>(c)));
  };
  std::size_t best = 0;
  std::pair<std::size_t, std::size_t> best_rank{0, 0};
  for (std::size_t i = 0; i + frames <= log.scans.size(); ++i) {
    std::size_t jump = 0, misdetected = 0;
    for (std::size_t k = i; k < i + frames; ++k) {
      jump += count(log.scans[k], PointCode::kJump);
      misdetected += count(log.scans[k], PointCode::kMisdetected);
    }
    const std::pair<std::size_t, std::size_t> rank{std::min(jump, misdetected), jump + misdetected};
    if (rank > best_rank) best_rank = rank, best = i;
  }
  return best;
}

// Every filter's labels on the same frames of one log, stacked.
void framesFigure(const std::string& path, const sim::LabelledLog& log, const std::vector<TunedFamily>& tuned) {
  // A log shorter than the window (--max-frames 5) is drawn whole.
  const std::size_t frames = std::min<std::size_t>(kFigureFrames, log.scans.size());
  if (frames == 0) return;
  const std::size_t first = busiestWindow(log, frames);
  std::vector<PngImage> rows;
  int width = 0, height = 0;
  const Logs one{sim::LabelledLog{log.name, log.sensor,
                                  std::vector<Scan>(log.scans.begin(),
                                                    log.scans.begin() + static_cast<std::ptrdiff_t>(first + frames))}};
  for (const auto& t : tuned) {
    accuracy::LogLabels labels;
    accuracy::scoreFamily(*t.family, t.tuned, one, &labels);  // from the log's start: multi-frame filters need their history
    ScanRenderer renderer;
    for (std::size_t i = first; i < first + frames; ++i) renderer.add(one[0].scans[i], log.sensor, labels[0][i]);
    rows.push_back(renderer.draw({.panel_pixels = kFigurePanelPixels, .title = t.family->name + " (tuned)"}));
    width = std::max(width, rows.back().width());
    height += rows.back().height();
  }
  PngImage figure(width, height);
  int y = 0;
  for (const auto& row : rows) figure.paste(row, 0, y), y += row.height();
  figure.save(path);
  std::cerr << "frames figure: " << log.name << " scans " << first << "-" << first + frames - 1 << "\n";
}

// `as_tested`: the tuned filters' scores on the built-in test logs when the
// comparison ran on them (the first variant is exactly those logs), else null.
void robustnessTables(std::ostream& out, const std::vector<TunedFamily>& tuned, const BenchAccuracyOptions& options,
                      const std::vector<ScoredFilter>* as_tested) {
  std::vector<SceneVariant> variants;
  const auto add = [&](const std::string& name) -> SceneVariant& {
    variants.push_back(unchangedScenes(options.sensor));
    variants.back().name = name;
    return variants.back();
  };
  add("unchanged scenes");
  add("range noise x2").noise_factor = 2.0;
  add("0.5° resolution (720 beams)").beams = 720;
  add("0.25° resolution (1440 beams)").beams = 1440;
  add("true poses (no odometry drift)").odometry = kNoDrift;
  add("odometry drift 3 %, 2°/m").odometry = sim::OdometryDrift{0.03, 2.0 * M_PI / 180.0};
  std::ostringstream ours, all;
  ours << "| variant | jump P / R / F1 | misdetected P / R / F1 | valid deleted | thin legs kept | µs / scan |\n"
       << "|---|---|---|---|---|---|\n";
  all << "| variant |";
  for (const auto& t : tuned) all << " " << t.family->name << " |";
  all << "\n|---|";
  for (std::size_t f = 0; f < tuned.size(); ++f) all << "---|";
  all << "\n";
  for (std::size_t v = 0; v < variants.size(); ++v) {
    const SceneVariant& variant = variants[v];
    const bool reuse = v == 0 && as_tested;
    std::cerr << "robustness: " << variant.name << "\n";
    const Logs logs = reuse ? Logs{} : accuracy::simulateBuiltinScenes(options.test_seeds, options.max_frames, variant);
    all << "| " << variant.name << " |";
    for (std::size_t f = 0; f < tuned.size(); ++f) {
      const ScoredFilter r = reuse ? (*as_tested)[f] : accuracy::scoreFamily(*tuned[f].family, tuned[f].tuned, logs);
      const RemovalScore& s = r.score;
      all << " " << fmt("%.3f", s.artefactF1()) << " (" << pct(s.falseDeletionRate()) << ") |";
      if (f == 0)
        ours << "| " << variant.name << " | " << prf(s, s.jump()) << " | " << prf(s, s.misdetected()) << " | "
             << pct(s.falseDeletionRate()) << " | " << fmt("%.1f %%", 100.0 * s.thinLegRetention()) << " | "
             << fmt("%.0f", r.micros_per_scan) << " |\n";
    }
    all << "\n";
  }
  out << "\n### Robustness of " << tuned[0].family->name << " (tuned parameters)\n\n" << ours.str()
      << "\n### Robustness, every filter: artefacts F1 (valid deleted)\n\n" << all.str();
}

}  // namespace

int runBenchAccuracy(const BenchAccuracyOptions& options) {
  const FilterConfig ours = options.config.empty() ? FilterConfig{} : loadFilterConfig(options.config);
  const auto families = accuracy::comparisonFamilies(ours);
  Logs tune_logs, test_logs;
  for (const auto& path : options.tune_logs) tune_logs.push_back(readLabelledLog(path));
  for (const auto& path : options.logs) test_logs.push_back(readLabelledLog(path));
  if (tune_logs.empty())
    tune_logs = accuracy::simulateBuiltinScenes({options.tune_seed}, options.max_frames, unchangedScenes(options.sensor));
  if (test_logs.empty())
    test_logs = accuracy::simulateBuiltinScenes(options.test_seeds, options.max_frames, unchangedScenes(options.sensor));

  std::vector<TunedFamily> tuned;
  std::vector<ScoredFilter> as_default, as_tuned;
  for (const auto& family : families) {
    std::cerr << "tuning " << family.name << " (" << options.budget << " evaluations at most)\n";
    tuned.push_back(accuracy::tuneFamily(family, tune_logs, options.budget));
    as_default.push_back(accuracy::scoreFamily(family, tuned.back().defaults, test_logs));
    as_tuned.push_back(accuracy::scoreFamily(family, tuned.back().tuned, test_logs));
  }

  std::ostringstream report;
  std::size_t test_scans = 0;
  for (const auto& log : test_logs) test_scans += log.scans.size();
  report << "Scored on " << test_logs.size() << " logs (" << test_scans << " scans); each filter tuned with at most "
         << options.budget << " evaluations on " << tune_logs.size()
         << " other logs, ranked by artefacts F1. Precision is class-agnostic: removed points of the class against "
            "valid points removed.\n\n";
  comparisonTable(report, tuned, as_default, as_tuned);
  report << "\n";
  causeTable(report, tuned, as_tuned);
  report << "\n| filter | source | evaluations | artefacts F1 on the tuning logs (tuned) |\n|---|---|---|---|\n";
  for (const auto& t : tuned)
    report << "| " << t.family->name << " | " << t.family->source << " | " << t.evaluations << " | "
           << fmt("%.3f", t.tuned_objective) << " |\n";
  if (options.robustness) robustnessTables(report, tuned, options, options.logs.empty() ? &as_tuned : nullptr);

  if (!options.output_dir.empty()) {
    std::filesystem::create_directories(options.output_dir);
    const std::filesystem::path dir(options.output_dir);
    prChart((dir / "compare-pr-jump.png").string(), "Jump points: precision / recall (tuned)", tuned, as_tuned, true);
    prChart((dir / "compare-pr-misdetected.png").string(), "Misdetected points: precision / recall (tuned)", tuned,
            as_tuned, false);
    causeChart((dir / "compare-recall-by-cause.png").string(), tuned, as_tuned);
    framesFigure((dir / "compare-frames.png").string(), test_logs.front(), tuned);
    std::ofstream((dir / "accuracy-comparison.md").string()) << report.str();
  }
  std::cout << report.str();
  return 0;
}

}  // namespace scanfilter::cli
