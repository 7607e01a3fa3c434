#include "scanfilter/sim/scan_simulator.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "scanfilter/point_code.hpp"
#include "scanfilter/scan_geometry.hpp"

namespace scanfilter::sim {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDegToRad = std::numbers::pi / 180.0;
// Secondary rays start this far off the surface so they do not hit it again.
constexpr double kSurfaceOffset = 1e-6;
// A displaced return counts as a jump point beyond this many σ of noise.
constexpr double kJumpSigmas = 4.0;

double wrapAngle(double a) { return std::atan2(std::sin(a), std::cos(a)); }
}  // namespace

ScanSimulator::ScanSimulator(Scene scene, std::uint64_t seed)
    : scene_(std::move(scene)), caster_(scene_), rng_(seed) {
  header_.source = "scanfilter simulate: scene " + scene_.name + ", seed " + std::to_string(seed);
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

std::optional<double> ScanSimulator::specularGhost(const Eigen::Vector2d& dir, const RayHit& hit) {
  const LidarModel& m = scene_.lidar;
  const double reach = scene_.sensor.range_max;
  const double p_specular = hit.material == Material::kGlass ? m.glass_specular_probability
                                                             : m.smooth_specular_probability;
  const double u = uniform_(rng_);
  Eigen::Vector2d onward;
  if (u < p_specular) {
    onward = dir - 2.0 * dir.dot(hit.normal) * hit.normal;  // mirror path
  } else if (hit.material == Material::kGlass && u < p_specular + m.glass_transmit_probability) {
    onward = dir;  // straight through the pane
  } else {
    return std::nullopt;
  }
  const auto second = caster_.cast(hit.point + kSurfaceOffset * onward, onward, reach);
  // The sensor reports the whole path length along the outgoing beam.
  if (!second) return kNaN;
  return hit.range + second->range;
}

ScanSimulator::Beam ScanSimulator::simulateBeam(const Eigen::Vector2d& origin, double angle) {
  const LidarModel& m = scene_.lidar;
  const SensorInfo& sensor = scene_.sensor;
  const Eigen::Vector2d dir(std::cos(angle), std::sin(angle));
  const auto hit = caster_.cast(origin, dir, sensor.range_max * 2.0);
  const Beam no_return{kNaN, static_cast<std::uint8_t>(PointCode::kNoReturn), false};
  if (!hit || hit->range > sensor.range_max) return no_return;
  const double truth_range = hit->range;

  double range = truth_range;
  bool displaced = false;
  std::uint8_t truth = static_cast<std::uint8_t>(PointCode::kValid);
  std::optional<double> ghost;
  if (hit->material != Material::kRough) ghost = specularGhost(dir, *hit);
  if (ghost) {
    if (std::isnan(*ghost)) return no_return;
    range = *ghost;
    if (range - truth_range > m.jump_min_error) truth = static_cast<std::uint8_t>(PointCode::kMisdetected);
  } else {
    if (hit->material == Material::kRough && chance(m.dropout_probability)) return no_return;
    // Mixed return: the footprint's two edges see surfaces at different depths.
    const double half_spot = 0.5 * m.spot_width_deg * kDegToRad;
    double near = truth_range;
    double far = truth_range;
    for (double offset : {-half_spot, half_spot}) {
      const Eigen::Vector2d d(std::cos(angle + offset), std::sin(angle + offset));
      const auto edge = caster_.cast(origin, d, sensor.range_max * 2.0);
      if (!edge) continue;  // nothing behind: no light to mix with
      near = std::min(near, edge->range);
      far = std::max(far, edge->range);
    }
    if (far - near > m.edge_gap && chance(m.mixed_probability)) {
      range = near + uniform_(rng_) * (far - near);
      displaced = true;
    }
    // Deformed spot at grazing incidence and at wall junctions.
    const double incidence = std::acos(std::min(1.0, std::abs(dir.dot(hit->normal))));
    if (incidence > m.grazing_angle_deg * kDegToRad && chance(m.grazing_probability)) {
      range += symmetric(m.grazing_error_max);
      displaced = true;
    }
    if (caster_.distanceToCorner(hit->point) < m.junction_radius && chance(m.junction_probability)) {
      range += symmetric(m.junction_error_max);
      displaced = true;
    }
  }
  range += sigma(truth_range) * normal_(rng_);
  range = std::round(range / m.range_resolution) * m.range_resolution;
  // A displaced return is a jump point when it lies on no surface at all: one
  // that slid along its own wall (grazing) or onto another one is still valid.
  if (displaced) {
    const double off_surface = caster_.distanceToSurface(origin + range * dir);
    if (off_surface > std::max(m.jump_min_error, kJumpSigmas * sigma(truth_range)))
      truth = static_cast<std::uint8_t>(PointCode::kJump);
  }
  if (range < sensor.range_min || range > sensor.range_max) return no_return;
  const bool thin = hit->is_leg && truth == static_cast<std::uint8_t>(PointCode::kValid);
  return {range, truth, thin};
}

bool ScanSimulator::next(ScanRecord& record) {
  if (frame_ >= poses_.size()) return false;
  record = ScanRecord{};
  Scan& scan = record.scan;
  const int beams = scene_.lidar.beams;
  scan.stamp = Stamp::fromSeconds(static_cast<double>(frame_) / scene_.lidar.rate_hz);
  scan.pose = poses_[frame_++];
  scan.angle_min = 0.0;
  scan.angle_increment = 2.0 * std::numbers::pi / beams;
  scan.ranges.resize(static_cast<std::size_t>(beams));
  scan.truth.resize(static_cast<std::size_t>(beams));
  const Eigen::Vector2d origin = sensorOrigin(scan.pose, scene_.sensor.mount);
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const Beam beam = simulateBeam(origin, beamWorldAngle(scan, scene_.sensor, i));
    scan.ranges[i] = beam.range;
    scan.truth[i] = beam.truth;
    if (beam.thin_leg) scan.thin_leg_beams.push_back(static_cast<std::uint32_t>(i));
  }
  return true;
}

}  // namespace scanfilter::sim
