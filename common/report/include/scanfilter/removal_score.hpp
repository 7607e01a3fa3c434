#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "scanfilter/artefact_cause.hpp"
#include "scanfilter/point_code.hpp"
#include "scanfilter/scan.hpp"

namespace scanfilter {

inline double f1Score(double precision, double recall) {
  return precision + recall > 0.0 ? 2.0 * precision * recall / (precision + recall) : 0.0;
}

// Precision, recall and F1 of removing one kind of artefact.
struct RemovalClassScore {
  std::size_t truth = 0;              // points of this kind in the truth
  std::size_t truth_removed = 0;      // of those, removed by any step
  std::size_t labelled = 0;           // points the filter gave this code
  std::size_t labelled_artefact = 0;  // of those, truly an artefact (jump or misdetected)

  double recall() const { return ratio(truth_removed, truth); }
  double precision() const { return ratio(labelled_artefact, labelled); }
  void add(const RemovalClassScore& o) {
    truth += o.truth;
    truth_removed += o.truth_removed;
    labelled += o.labelled;
    labelled_artefact += o.labelled_artefact;
  }
  double f1() const { return f1Score(precision(), recall()); }
  static double ratio(std::size_t a, std::size_t b) { return b ? static_cast<double>(a) / static_cast<double>(b) : 1.0; }
};

// Range bands of the false-deletion figures: [0, 2), [2, 4), [4, inf) m
// (with a 0.15-6 m sensor: 0.15-2, 2-4 and 4-6 m).
inline constexpr std::array<double, 2> kRangeBandEdges = {2.0, 4.0};
inline constexpr std::size_t kRangeBandCount = kRangeBandEdges.size() + 1;
std::size_t rangeBand(double range);

// Accumulates a filter's labels against the truth over many scans.
// Scans without truth only add to the per-code counts.
class RemovalScore {
 public:
  void add(const Scan& scan, std::span<const std::uint8_t> labels);
  // Merges another score (e.g. of another log) into this one.
  void add(const RemovalScore& other);

  std::size_t frames() const { return frames_; }
  std::size_t labelCount(PointCode code) const { return label_counts_[static_cast<std::size_t>(code)]; }
  bool hasTruth() const { return truth_frames_ > 0; }
  const RemovalClassScore& jump() const { return jump_; }
  const RemovalClassScore& misdetected() const { return misdetected_; }
  std::size_t validTruth() const { return valid_truth_; }
  std::size_t validDeleted() const { return valid_deleted_; }
  double falseDeletionRate() const { return RemovalClassScore::ratio(valid_deleted_, valid_truth_); }
  std::size_t thinLegTruth() const { return thin_truth_; }
  std::size_t thinLegKept() const { return thin_kept_; }
  double thinLegRetention() const { return RemovalClassScore::ratio(thin_kept_, thin_truth_); }
  // Artefacts of one cause (simulator ground truth, `truth_cause`) and the
  // share of them removed, whatever step removed them.
  std::size_t causeTruth(ArtefactCause cause) const { return cause_truth_[static_cast<std::size_t>(cause)]; }
  double causeRecall(ArtefactCause cause) const {
    const auto c = static_cast<std::size_t>(cause);
    return RemovalClassScore::ratio(cause_removed_[c], cause_truth_[c]);
  }
  double falseDeletionRate(std::size_t band) const {
    return RemovalClassScore::ratio(valid_deleted_by_band_[band], valid_truth_by_band_[band]);
  }

  // Class-agnostic figures, for filters that remove without saying why (the
  // baselines): precision of removing class c counts the removed points of c
  // against the valid points removed, whatever code either got.
  double removalPrecision(const RemovalClassScore& c) const {
    return RemovalClassScore::ratio(c.truth_removed, c.truth_removed + valid_deleted_);
  }
  double removalF1(const RemovalClassScore& c) const { return f1Score(removalPrecision(c), c.recall()); }
  // Both artefact kinds as one class against the valid points.
  double artefactPrecision() const {
    const std::size_t removed = jump_.truth_removed + misdetected_.truth_removed;
    return RemovalClassScore::ratio(removed, removed + valid_deleted_);
  }
  double artefactRecall() const {
    return RemovalClassScore::ratio(jump_.truth_removed + misdetected_.truth_removed, jump_.truth + misdetected_.truth);
  }
  double artefactF1() const { return f1Score(artefactPrecision(), artefactRecall()); }

 private:
  std::size_t frames_ = 0;
  std::size_t truth_frames_ = 0;
  std::array<std::size_t, kPointCodeCount> label_counts_{};
  RemovalClassScore jump_;
  RemovalClassScore misdetected_;
  std::size_t valid_truth_ = 0;
  std::size_t valid_deleted_ = 0;
  std::size_t thin_truth_ = 0;
  std::size_t thin_kept_ = 0;
  std::array<std::size_t, kArtefactCauseCount> cause_truth_{};
  std::array<std::size_t, kArtefactCauseCount> cause_removed_{};
  std::array<std::size_t, kRangeBandCount> valid_truth_by_band_{};
  std::array<std::size_t, kRangeBandCount> valid_deleted_by_band_{};
};

}  // namespace scanfilter
