#pragma once
#include <algorithm>

#include "scanfilter/range_noise_sampling.hpp"

namespace scanfilter {

// Which range sets the minimum tangential length l of equation (7). The paper
// writes d_i (the seed) in l and d_ave in the arctangent; per-cluster wants
// d_ave in both (docs/algorithm.md).
enum class SpanRange { kClusterMean, kSeed };

// Parameters of step 1, equations (5)-(7). Defaults are the values chosen by
// the sweep in docs/accuracy.md; config/filter.yaml documents every key.
struct JumpFilterParams {
  double angular_accuracy_deg = 1.0;  // Δθ, the sensor's angular accuracy
  double alpha = 0.6;                 // α, magnification of the neighbour radius
  double theta_k_deg = 70.0;          // θK, largest surface-to-tangent angle allowed
  double l_min = 0.01;                // m, minimum tangential length at d_min
  double l_max = 0.10;                // m, minimum tangential length at d_max
  double d_min = 0.15;                // m, sensor's minimum range
  double d_max = 6.0;                 // m, sensor's maximum range
  SpanRange span_range = SpanRange::kClusterMean;
  // Beyond the paper: a return that lies off both lines through its angular
  // neighbours on either side (each a straight run of three returns) by more
  // than the range noise allows is no surface point, whatever cluster it
  // joined (off_surface_check.hpp).
  bool off_surface_check = true;
  double off_surface_min = 0.05;          // m, smallest offset that counts
  double off_surface_sigmas = 4.0;        // offsets within this many σ(range) are noise
  double noise_sigma_base = 0.003;        // m, the sensor's range noise σ at zero range
  double noise_sigma_quadratic = 0.001;   // m per m²: σ(d) = base + quadratic·d² (triangulation)
  // Beyond the paper: σ(d) measured on the scans (range_noise_estimate.hpp);
  // each measured term replaces the one above when larger. false = the
  // configured model always.
  bool noise_estimate = true;
  RangeNoiseSampling noise_sampling;  // noise_estimate_window_scans, noise_estimate_min_samples
  // Beyond the paper: eq. 5's radius widened by this many σ(range) (the noise
  // model above), so that range noise alone does not split a surface (at
  // 0.1° steps σ exceeds eq. 5's radius from about 1 m). 0 = the paper.
  double radius_noise_sigmas = 3.0;
  // Beyond the paper: a wall seen at grazing incidence has its returns far
  // apart (range·Δθ / cos incidence), farther than eq. 5's radius, so it falls
  // apart into clusters small enough for eq. 7 to delete. Consecutive returns
  // on one straight line (each within the off-surface tolerance of the line
  // through its neighbours), at most as far apart as a surface at
  // `straight_run_max_incidence_deg` would put them, join one cluster when
  // the run has at least `straight_run_min_points` returns (a short run of
  // mixed returns between an edge and its background is no surface).
  bool straight_runs = true;
  double straight_run_max_incidence_deg = 85.0;
  int straight_run_min_points = 5;
  // Beyond the paper: a cluster too short for eq. 7 is still kept when it
  // stands in front of what the sensor sees on both sides of it: the beams
  // just outside it return farther by more than the off-surface tolerance,
  // or nothing (a table or chair leg, a pole). A mixed return at an edge lies
  // between the edge's range and the background's, never in front of both;
  // but the mixed return of an object thinner than a beam does stand in
  // front, so the option trades jump recall for thin obstacles kept
  // (measured in docs/beyond-the-paper.md, 11).
  bool keep_foreground_clusters = true;
  // Beyond the paper: a lone return is kept when the beams at its range lie
  // at least l_max apart (range·Δθ >= l_max: beyond 5.7 m at 1°). There an
  // object as wide as the smallest eq. 7 keeps shows as this one return, so
  // eq. 7 cannot tell it from an artefact; far walls at an angle, posts and
  // door frames are such returns.
  bool keep_unresolved_returns = true;
};

// σ(d) = base + quadratic·d², the range-noise model of step 1: the two
// noise_sigma_* parameters, or what the estimate replaced them with.
struct RangeNoiseModel {
  double base = 0.0;       // m
  double quadratic = 0.0;  // m per m²
  double sigmaAt(double range) const { return base + quadratic * range * range; }
  bool operator==(const RangeNoiseModel&) const = default;
};

inline RangeNoiseModel noiseModelOf(const JumpFilterParams& p) {
  return {p.noise_sigma_base, p.noise_sigma_quadratic};
}

inline void setNoiseModel(JumpFilterParams& p, const RangeNoiseModel& m) {
  p.noise_sigma_base = m.base;
  p.noise_sigma_quadratic = m.quadratic;
}

// The sensor's range noise σ(range) of the noise model above.
inline double rangeNoiseSigma(const JumpFilterParams& p, double range) {
  return p.noise_sigma_base + p.noise_sigma_quadratic * range * range;
}

// How far off a line a return may lie and still be on it: the smallest
// offset that counts, or off_surface_sigmas · σ(range) when larger.
inline double offSurfaceTolerance(const JumpFilterParams& p, double range) {
  return std::max(p.off_surface_min, p.off_surface_sigmas * rangeNoiseSigma(p, range));
}

}  // namespace scanfilter
