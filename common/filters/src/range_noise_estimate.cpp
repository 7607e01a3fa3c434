#include "scanfilter/range_noise_estimate.hpp"

#include <algorithm>
#include <cmath>

#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {

namespace {
// A plane seen at more than this incidence puts its returns far apart along
// the beam, and the line through two of them says little about the third.
constexpr double kMinCosIncidence = 0.5;  // 60°
// Returns of one plane at moderate incidence are about evenly spaced; a
// triple spaced more unevenly than this straddles two objects.
constexpr double kMaxSpacingRatio = 2.0;
// Median absolute deviation to σ for normally distributed residuals.
constexpr double kMadToSigma = 1.4826;
// A residual holds the point's own noise and half of each neighbour's.
const double kResidualPerSigma = std::sqrt(1.5);
// Quarter-octave thresholds of a mantissa in [1, 2): 2^0.25, 2^0.5, 2^0.75.
constexpr double kQuarterOctaves[] = {1.189207115002721, 1.414213562373095, 1.681792830507429};
}  // namespace

RangeNoiseEstimate::RangeNoiseEstimate(const JumpFilterParams& params)
    : RangeNoiseEstimate(noiseModelOf(params), params.noise_sampling, params.d_max) {}

RangeNoiseEstimate::RangeNoiseEstimate(const RangeNoiseModel& floor, const RangeNoiseSampling& sampling,
                                       double max_range)
    : configured_(floor),
      model_(configured_),
      keep_(1.0 - 1.0 / sampling.window_scans),
      min_samples_(sampling.min_samples),
      bands_(std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(max_range / kBandWidth))), Histogram{}),
      band_weight_(bands_.size(), 0.0) {}

bool RangeNoiseEstimate::residual(const Eigen::Vector2d& a, const Eigen::Vector2d& p, const Eigen::Vector2d& b,
                                  double range, double& out) {
  if (!a.allFinite() || !b.allFinite() || !(range > 0.0)) return false;
  // Squared comparisons throughout: this runs on every beam.
  const Eigen::Vector2d along = b - a;
  const double length_sq = along.squaredNorm();
  const double across = cross(p, along) / range;  // |beam × along|: length · cos(incidence)
  if (!(length_sq > 0.0) || across * across < kMinCosIncidence * kMinCosIncidence * length_sq) return false;
  const double left_sq = (p - a).squaredNorm(), right_sq = (b - p).squaredNorm();
  constexpr double kRatioSq = kMaxSpacingRatio * kMaxSpacingRatio;
  if (left_sq > kRatioSq * right_sq || right_sq > kRatioSq * left_sq) return false;
  // Where the beam meets the line a + s·(b - a): t·beam = a + s·along.
  out = range - cross(a, along) / across;
  return true;
}

int RangeNoiseEstimate::binOf(double magnitude) {
  if (!(magnitude > kSmallest)) return 0;
  if (magnitude >= kLargest) return kBins - 1;  // the overflow bin
  int exponent = 0;
  const double mantissa = 2.0 * std::frexp(magnitude / kSmallest, &exponent);  // [1, 2)
  int bin = kBinsPerOctave * (exponent - 1);
  for (double q : kQuarterOctaves) bin += mantissa >= q;
  return std::min(bin, kBins - 2);
}

void RangeNoiseEstimate::add(std::span<const Eigen::Vector2d> points, std::span<const double> ranges,
                             bool full_turn) {
  for (auto& h : bands_)
    for (double& w : h) w *= keep_;
  for (double& w : band_weight_) w *= keep_;
  const std::size_t n = points.size();
  if (n < 3) return;
  for (std::size_t i = 0; i < n; ++i) {
    if (!full_turn && (i == 0 || i + 1 == n)) continue;
    const Eigen::Vector2d& p = points[i];
    if (!p.allFinite()) continue;
    double r = 0.0;
    if (!residual(points[(i + n - 1) % n], p, points[(i + 1) % n], ranges[i], r)) continue;
    const auto band = std::min(bands_.size() - 1, static_cast<std::size_t>(ranges[i] / kBandWidth));
    bands_[band][static_cast<std::size_t>(binOf(std::abs(r)))] += 1.0;
    band_weight_[band] += 1.0;
  }
  refit();
}

double RangeNoiseEstimate::bandSigma(std::size_t band) const {
  if (band >= bands_.size() || band_weight_[band] < min_samples_) return 0.0;
  // The median, interpolated geometrically within its bin.
  const double half = band_weight_[band] / 2.0;
  double below = 0.0;
  for (int k = 0; k < kBins; ++k) {
    const double w = bands_[band][static_cast<std::size_t>(k)];
    if (below + w >= half && w > 0.0) {
      if (k == kBins - 1) return 0.0;  // most residuals beyond kLargest: no surface (ghosts, clutter)
      const double fraction = (half - below) / w;
      const double median = kSmallest * std::exp2((k + fraction) / kBinsPerOctave);
      return kMadToSigma * median / kResidualPerSigma;
    }
    below += w;
  }
  return 0.0;
}

std::optional<RangeNoiseModel> RangeNoiseEstimate::fit(const RangeNoiseModel* previous) const {
  // Weighted least squares of σ = base + quadratic·d² over the bands, d the band's middle.
  double sw = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  int bands = 0;
  for (std::size_t b = 0; b < bands_.size(); ++b) {
    const double sigma = bandSigma(b);
    if (!(sigma > 0.0)) continue;
    const double d = (static_cast<double>(b) + 0.5) * kBandWidth;
    const double x = d * d, w = band_weight_[b];
    if (previous) {  // the second pass leaves out bands far off the first fit
      const double expected = previous->base + previous->quadratic * x;
      if (sigma > kOutlierFactor * expected || sigma * kOutlierFactor < expected) continue;
    }
    sw += w, sx += w * x, sy += w * sigma, sxx += w * x * x, sxy += w * x * sigma;
    ++bands;
  }
  if (bands < 2) return std::nullopt;
  const double det = sw * sxx - sx * sx;
  RangeNoiseModel m{(sxx * sy - sx * sxy) / det, (sw * sxy - sx * sy) / det};
  if (m.quadratic < 0.0) m = {sy / sw, 0.0};   // flat: time of flight
  else if (m.base < 0.0) m = {0.0, sxy / sxx};  // through the origin
  return m;
}

void RangeNoiseEstimate::refit() {
  std::optional<RangeNoiseModel> m = fit(nullptr);
  if (m) m = fit(&*m);
  // The configured model is the floor of each term: the estimate only widens
  // step 1's tolerances (see the header).
  model_ = configured_;
  if (m) model_ = {std::max(m->base, configured_.base), std::max(m->quadratic, configured_.quadratic)};
}

}  // namespace scanfilter
