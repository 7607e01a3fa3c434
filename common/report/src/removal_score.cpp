#include "scanfilter/removal_score.hpp"

#include "scanfilter/value_band.hpp"

namespace scanfilter {

std::size_t rangeBand(double range) { return bandOf(range, kRangeBandEdges); }

void RemovalScore::add(const Scan& scan, std::span<const std::uint8_t> labels) {
  ++frames_;
  for (std::uint8_t code : labels) ++label_counts_[code];
  if (scan.truth.empty()) return;
  ++truth_frames_;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const auto truth = static_cast<PointCode>(scan.truth[i]);
    const auto label = static_cast<PointCode>(labels[i]);
    // A removed artefact counts for the kind of artefact it truly is, whichever step removed it.
    if (truth == PointCode::kJump) {
      ++jump_.truth;
      jump_.truth_removed += isRemovedCode(labels[i]);
    } else if (truth == PointCode::kMisdetected) {
      ++misdetected_.truth;
      misdetected_.truth_removed += isRemovedCode(labels[i]);
    } else if (truth == PointCode::kValid) {
      ++valid_truth_;
      valid_deleted_ += isRemovedCode(labels[i]);
      const std::size_t band = rangeBand(scan.ranges[i]);
      ++valid_truth_by_band_[band];
      valid_deleted_by_band_[band] += isRemovedCode(labels[i]);
    }
    RemovalClassScore* by_label = label == PointCode::kJump ? &jump_
                                  : label == PointCode::kMisdetected ? &misdetected_
                                                                     : nullptr;
    if (by_label) {
      ++by_label->labelled;
      by_label->labelled_artefact += isRemovedCode(scan.truth[i]);
    }
  }
  for (std::size_t i = 0; i < scan.truth_cause.size() && i < labels.size(); ++i) {
    const std::uint8_t cause = scan.truth_cause[i];
    // The reader rejects unknown causes; a scan built in code may hold one.
    if (cause == static_cast<std::uint8_t>(ArtefactCause::kNone) || !isValidArtefactCause(cause)) continue;
    ++cause_truth_[cause];
    cause_removed_[cause] += isRemovedCode(labels[i]);
  }
  for (std::uint32_t beam : scan.thin_leg_beams) {
    ++thin_truth_;
    thin_kept_ += labels[beam] == static_cast<std::uint8_t>(PointCode::kValid);
  }
}

void RemovalScore::add(const RemovalScore& o) {
  frames_ += o.frames_;
  truth_frames_ += o.truth_frames_;
  for (std::size_t c = 0; c < label_counts_.size(); ++c) label_counts_[c] += o.label_counts_[c];
  jump_.add(o.jump_);
  misdetected_.add(o.misdetected_);
  valid_truth_ += o.valid_truth_;
  valid_deleted_ += o.valid_deleted_;
  thin_truth_ += o.thin_truth_;
  thin_kept_ += o.thin_kept_;
  for (std::size_t c = 0; c < cause_truth_.size(); ++c) {
    cause_truth_[c] += o.cause_truth_[c];
    cause_removed_[c] += o.cause_removed_[c];
  }
  for (std::size_t b = 0; b < kRangeBandCount; ++b) {
    valid_truth_by_band_[b] += o.valid_truth_by_band_[b];
    valid_deleted_by_band_[b] += o.valid_deleted_by_band_[b];
  }
}

}  // namespace scanfilter
