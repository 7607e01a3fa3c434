#pragma once
#include <cstdint>
#include <random>
#include <vector>

#include "scanfilter/artefact_cause.hpp"
#include "scanfilter/scan_source.hpp"
#include "scanfilter/sim/range_mixing.hpp"
#include "scanfilter/sim/ray_caster.hpp"
#include "scanfilter/sim/scene.hpp"

namespace scanfilter::sim {

// Labelled scans of a scene along its trajectory, as the scene's LiDAR model
// (scene.lidar) sees it: mixed returns where the beam's footprint straddles a
// depth step (jump points when they lie on no surface), specular ghosts and
// returns through glass (misdetected points), range noise, and the poses as
// drifting odometry records them (scene.odometry) while the truth comes from
// the true poses. Same scene and seed, same scans.
class ScanSimulator final : public ScanSource {
 public:
  ScanSimulator(Scene scene, std::uint64_t seed);

  const ScanLogHeader& header() const override { return header_; }
  bool next(ScanRecord& record) override;

  const Scene& scene() const { return scene_; }
  // Where the robot really was for the scan next() gave last; the scan's
  // pose is what its odometry recorded.
  const Pose2& truePose() const { return true_pose_; }

 private:
  struct Beam {
    double range;
    std::uint8_t truth;
    bool thin_leg;
    ArtefactCause cause;  // kNone unless truth is an artefact
  };
  // A beam that left the first surface it met: where it came back from.
  struct SecondPath {
    double range;         // the whole path length; NaN: it never came back
    ArtefactCause cause;  // mirrored or through a pane
  };
  // A deformed spot's displacement along the beam, and what deformed it.
  struct Displacement {
    double shift = 0.0;
    ArtefactCause cause = ArtefactCause::kNone;
  };
  void planPoses();
  Beam simulateBeam(const Eigen::Vector2d& origin, double angle);
  // The light coming back from every part of the beam's footprint.
  const std::vector<PartialReturn>& footprint(const Eigen::Vector2d& origin, double angle);
  // How well a surface returns light straight back along `dir`.
  double directReturn(const Eigen::Vector2d& dir, const RayHit& hit) const;
  // The path of a mirrored or transmitted beam, or nothing when the surface
  // returned the beam directly.
  std::optional<SecondPath> specularPath(const Eigen::Vector2d& dir, const RayHit& hit);
  // Random displacement of a deformed spot (grazing incidence, junctions).
  Displacement deformation(const Eigen::Vector2d& dir, const RayHit& hit);
  // Why a direct return that lies on no surface is off it: the mix of the
  // footprint's parts (at mixed_range along dir), or else the displacement.
  ArtefactCause jumpCause(const Eigen::Vector2d& origin, const Eigen::Vector2d& dir, double mixed_range,
                          const std::vector<PartialReturn>& parts, const Displacement& displacement) const;
  double sigma(double range) const;
  // How far off every surface a direct return must lie to be a jump point.
  double jumpThreshold(double range) const;
  bool chance(double p) { return uniform_(rng_) < p; }
  double symmetric(double max) { return (2.0 * uniform_(rng_) - 1.0) * max; }

  Scene scene_;
  RayCaster caster_;
  ScanLogHeader header_;
  std::vector<Pose2> poses_;  // true poses, one per scan
  DeadReckoning odometry_;
  Pose2 true_pose_;
  std::size_t frame_ = 0;
  std::mt19937_64 rng_;
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
  std::normal_distribution<double> normal_{0.0, 1.0};
  std::vector<PartialReturn> parts_;  // footprint()'s result, reused
  std::vector<int> sweep_slots_;      // footprint()'s sample order, reused
};

}  // namespace scanfilter::sim
