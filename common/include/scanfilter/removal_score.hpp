#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "scanfilter/point_code.hpp"
#include "scanfilter/scan.hpp"

namespace scanfilter {

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
  double f1() const {
    const double p = precision(), r = recall();
    return p + r > 0.0 ? 2.0 * p * r / (p + r) : 0.0;
  }
  static double ratio(std::size_t a, std::size_t b) { return b ? static_cast<double>(a) / static_cast<double>(b) : 1.0; }
};

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
};

}  // namespace scanfilter
