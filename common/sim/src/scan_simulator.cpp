#include "scanfilter/sim/scan_simulator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

#include "scanfilter/point_code.hpp"
#include "scanfilter/scan_geometry.hpp"
#include "scanfilter/sim/specular_return.hpp"

namespace scanfilter::sim {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDegToRad = std::numbers::pi / 180.0;
constexpr double kMradToRad = 1e-3;
// Secondary rays start this far off the surface so they do not hit it again.
constexpr double kSurfaceOffset = 1e-6;
// A displaced return counts as a jump point beyond this many σ of noise.
constexpr double kJumpSigmas = 4.0;

double wrapAngle(double a) { return std::atan2(std::sin(a), std::cos(a)); }
}  // namespace

ScanSimulator::ScanSimulator(Scene scene, std::uint64_t seed)
    : scene_(std::move(scene)), caster_(scene_), odometry_(scene_.odometry), rng_(seed) {
  header_.source = "scanfilter simulate: scene " + scene_.name +
                   (scene_.sensor_preset.empty() ? "" : ", sensor " + scene_.sensor_preset) + ", " +
                   std::to_string(scene_.lidar.beams) + " beams, " + describe(scene_.odometry) + ", seed " +
                   std::to_string(seed);
  header_.sensor = scene_.sensor;
  planPoses();
}

void ScanSimulator::planPoses() {
  // Drive each leg of the path at constant speed after turning in place
  // towards it; one pose per scan period.
  const Trajectory& t = scene_.trajectory;
  const double dt = 1.0 / scene_.lidar.rate_hz;
  const double step = t.speed * dt;
  const double turn_step = t.turn_rate_deg * kDegToRad * dt;
  const auto heading = [&](std::size_t k) {
    const Eigen::Vector2d d = t.waypoints[k + 1] - t.waypoints[k];
    return std::atan2(d.y(), d.x());
  };
  double theta = heading(0);
  for (std::size_t k = 0; k + 1 < t.waypoints.size(); ++k) {
    const double target = heading(k);
    for (double diff = wrapAngle(target - theta); std::abs(diff) > turn_step; diff = wrapAngle(target - theta)) {
      theta = wrapAngle(theta + std::copysign(turn_step, diff));
      poses_.push_back({t.waypoints[k].x(), t.waypoints[k].y(), theta});
    }
    theta = target;
    const Eigen::Vector2d a = t.waypoints[k];
    const Eigen::Vector2d b = t.waypoints[k + 1];
    const double length = (b - a).norm();
    for (double s = 0.0; s < length; s += step) {
      const Eigen::Vector2d p = a + (b - a) * (s / length);
      poses_.push_back({p.x(), p.y(), theta});
    }
  }
}

double ScanSimulator::sigma(double range) const {
  return scene_.lidar.noise_sigma_base + scene_.lidar.noise_sigma_quadratic * range * range;
}

double ScanSimulator::jumpThreshold(double range) const {
  return std::max(scene_.lidar.jump_min_error, kJumpSigmas * sigma(range));
}

double ScanSimulator::directReturn(const Eigen::Vector2d& dir, const RayHit& hit) const {
  if (hit.material == Material::kRough) return 1.0;
  const double incidence = std::acos(std::min(1.0, std::abs(dir.dot(hit.normal))));
  const LidarModel& m = scene_.lidar;
  return directReturnProbability(hit.material == Material::kGlass ? m.glass : m.smooth, incidence);
}

std::optional<ScanSimulator::SecondPath> ScanSimulator::specularPath(const Eigen::Vector2d& dir, const RayHit& hit) {
  if (chance(directReturn(dir, hit))) return std::nullopt;
  const double incidence = std::acos(std::min(1.0, std::abs(dir.dot(hit.normal))));
  Eigen::Vector2d onward = dir - 2.0 * dir.dot(hit.normal) * hit.normal;  // mirror path
  ArtefactCause cause = ArtefactCause::kMirrorGhost;
  if (hit.material == Material::kGlass && !chance(paneReflectance(incidence, scene_.lidar.glass_refractive_index))) {
    onward = dir;  // straight through the pane
    cause = ArtefactCause::kThroughPane;
  }
  const auto second = caster_.cast(hit.point + kSurfaceOffset * onward, onward, scene_.sensor.range_max);
  // The sensor reports the whole path length along the outgoing beam.
  if (!second) return SecondPath{kNaN, cause};
  return SecondPath{hit.range + second->range, cause};
}

const std::vector<PartialReturn>& ScanSimulator::footprint(const Eigen::Vector2d& origin, double angle) {
  // Rays spread over the spot (stratified, so the fraction on each surface is
  // sampled evenly) and, in an independently shuffled order, over the angle
  // the head turns while the receiver integrates (a Latin hypercube).
  const LidarModel& m = scene_.lidar;
  const int n = m.footprint_rays;
  const double divergence = m.beam_divergence_mrad * kMradToRad;
  const double sweep = m.exposure_sweep * 2.0 * std::numbers::pi / m.beams;
  const Eigen::Vector2d across(-std::sin(angle), std::cos(angle));
  sweep_slots_.resize(static_cast<std::size_t>(n));
  std::iota(sweep_slots_.begin(), sweep_slots_.end(), 0);
  std::shuffle(sweep_slots_.begin(), sweep_slots_.end(), rng_);
  parts_.clear();
  for (int k = 0; k < n; ++k) {
    const double s = (k + uniform_(rng_)) / n - 0.5;
    const double t = (sweep_slots_[static_cast<std::size_t>(k)] + uniform_(rng_)) / n - 0.5;
    const double a = angle + s * divergence + t * sweep;
    const Eigen::Vector2d d(std::cos(a), std::sin(a));
    // Light from beyond range_max is too weak to count.
    const auto hit = caster_.cast(origin + s * m.exit_aperture * across, d, scene_.sensor.range_max);
    if (hit) parts_.push_back({hit->range, directReturn(d, *hit), hit->is_leg});
  }
  return parts_;
}

ScanSimulator::Displacement ScanSimulator::deformation(const Eigen::Vector2d& dir, const RayHit& hit) {
  const LidarModel& m = scene_.lidar;
  Displacement grazing, junction;
  const double incidence = std::acos(std::min(1.0, std::abs(dir.dot(hit.normal))));
  if (incidence > m.grazing_angle_deg * kDegToRad && chance(m.grazing_probability))
    grazing = {symmetric(m.grazing_error_max), ArtefactCause::kGrazingDisplacement};
  if (caster_.distanceToCorner(hit.point) < m.junction_radius && chance(m.junction_probability))
    junction = {symmetric(m.junction_error_max), ArtefactCause::kJunctionDisplacement};
  // Both may deform one spot: the larger displacement names the cause.
  const bool grazing_larger = std::abs(grazing.shift) >= std::abs(junction.shift);
  return {grazing.shift + junction.shift, grazing_larger ? grazing.cause : junction.cause};
}

ArtefactCause ScanSimulator::jumpCause(const Eigen::Vector2d& origin, const Eigen::Vector2d& dir, double mixed_range,
                                       const std::vector<PartialReturn>& parts,
                                       const Displacement& displacement) const {
  const bool mix_alone_is_off = caster_.distanceToSurface(origin + mixed_range * dir) > jumpThreshold(mixed_range);
  if (!mix_alone_is_off && displacement.cause != ArtefactCause::kNone) return displacement.cause;
  const bool on_thin_leg = std::any_of(parts.begin(), parts.end(), [](const PartialReturn& p) { return p.on_thin_leg; });
  return on_thin_leg ? ArtefactCause::kThinObjectMix : ArtefactCause::kEdgeMix;
}

ScanSimulator::Beam ScanSimulator::simulateBeam(const Eigen::Vector2d& origin, double angle) {
  const LidarModel& m = scene_.lidar;
  const SensorInfo& sensor = scene_.sensor;
  const Eigen::Vector2d dir(std::cos(angle), std::sin(angle));
  const auto hit = caster_.cast(origin, dir, sensor.range_max);
  const Beam no_return{kNaN, static_cast<std::uint8_t>(PointCode::kNoReturn), false, ArtefactCause::kNone};
  if (!hit) return no_return;

  double range = hit->range;
  auto truth = static_cast<std::uint8_t>(PointCode::kValid);
  ArtefactCause cause = ArtefactCause::kNone;
  std::optional<SecondPath> ghost;
  if (hit->material != Material::kRough) ghost = specularPath(dir, *hit);
  if (ghost) {
    if (std::isnan(ghost->range)) return no_return;
    range = ghost->range;
    if (range - hit->range > m.jump_min_error) {
      truth = static_cast<std::uint8_t>(PointCode::kMisdetected);
      cause = ghost->cause;
    }
  } else {
    if (hit->material == Material::kRough && chance(m.dropout_probability)) return no_return;
    const std::vector<PartialReturn>& parts = footprint(origin, angle);
    const double mixed = mixRanges(m.mixing, parts);
    if (!std::isnan(mixed)) range = mixed;
    const double mixed_range = range;
    const Displacement displacement = deformation(dir, *hit);
    range += displacement.shift;
    // A return is a jump point when it lies on no surface at all: one that
    // slid along its own wall (grazing) or onto another one is still valid.
    if (caster_.distanceToSurface(origin + range * dir) > jumpThreshold(range)) {
      truth = static_cast<std::uint8_t>(PointCode::kJump);
      cause = jumpCause(origin, dir, mixed_range, parts, displacement);
    }
  }
  range += sigma(range) * normal_(rng_);
  range = std::round(range / m.range_resolution) * m.range_resolution;
  if (range < sensor.range_min || range > sensor.range_max) return no_return;
  const bool thin = hit->is_leg && truth == static_cast<std::uint8_t>(PointCode::kValid);
  return {range, truth, thin, cause};
}

bool ScanSimulator::next(ScanRecord& record) {
  if (frame_ >= poses_.size()) return false;
  record = ScanRecord{};
  Scan& scan = record.scan;
  const int beams = scene_.lidar.beams;
  scan.stamp = Stamp::fromSeconds(static_cast<double>(frame_) / scene_.lidar.rate_hz);
  true_pose_ = poses_[frame_++];
  scan.pose = true_pose_;  // the beams leave from where the robot really is
  scan.angle_min = 0.0;
  scan.angle_increment = 2.0 * std::numbers::pi / beams;
  scan.ranges.resize(static_cast<std::size_t>(beams));
  scan.truth.resize(static_cast<std::size_t>(beams));
  scan.truth_cause.resize(static_cast<std::size_t>(beams));
  const Eigen::Vector2d origin = sensorOrigin(scan.pose, scene_.sensor.mount);
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const Beam beam = simulateBeam(origin, beamWorldAngle(scan, scene_.sensor, i));
    scan.ranges[i] = beam.range;
    scan.truth[i] = beam.truth;
    scan.truth_cause[i] = static_cast<std::uint8_t>(beam.cause);
    if (beam.thin_leg) scan.thin_leg_beams.push_back(static_cast<std::uint32_t>(i));
  }
  // The log holds what odometry recorded; without drift, the true pose
  // exactly (not re-integrated with rounding).
  if (!scene_.odometry.none()) scan.pose = odometry_.next(true_pose_);
  return true;
}

}  // namespace scanfilter::sim
