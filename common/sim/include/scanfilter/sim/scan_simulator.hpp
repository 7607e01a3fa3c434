#pragma once
#include <cstdint>
#include <random>
#include <vector>

#include "scanfilter/scan_source.hpp"
#include "scanfilter/sim/ray_caster.hpp"
#include "scanfilter/sim/scene.hpp"

namespace scanfilter::sim {

// Labelled scans of a scene along its trajectory: range noise growing with the
// square of the range (triangulation), mixed returns where the beam footprint
// straddles a depth step, displaced returns at grazing incidence and at wall
// junctions (jump points), and specular ghosts behind smooth walls and glass
// (misdetected points). Same scene and seed, same scans.
class ScanSimulator final : public ScanSource {
 public:
  ScanSimulator(Scene scene, std::uint64_t seed);

  const ScanLogHeader& header() const override { return header_; }
  bool next(ScanRecord& record) override;

  const Scene& scene() const { return scene_; }

 private:
  struct Beam {
    double range;
    std::uint8_t truth;
    bool thin_leg;
  };
  void planPoses();
  Beam simulateBeam(const Eigen::Vector2d& origin, double angle);
  // The path length of a mirrored or transmitted beam (NaN: it never comes
  // back), or nothing when the surface returned the beam normally.
  std::optional<double> specularGhost(const Eigen::Vector2d& dir, const RayHit& hit);
  double sigma(double range) const;
  bool chance(double p) { return uniform_(rng_) < p; }
  double symmetric(double max) { return (2.0 * uniform_(rng_) - 1.0) * max; }

  Scene scene_;
  RayCaster caster_;
  ScanLogHeader header_;
  std::vector<Pose2> poses_;
  std::size_t frame_ = 0;
  std::mt19937_64 rng_;
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
  std::normal_distribution<double> normal_{0.0, 1.0};
};

}  // namespace scanfilter::sim
