#pragma once
#include <cmath>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "scanfilter/beam_bundle.hpp"
#include "scanfilter/beam_mask.hpp"
#include "scanfilter/edge_smear_zone.hpp"
#include "scanfilter/evidence_radius.hpp"
#include "scanfilter/frame_alignment.hpp"
#include "scanfilter/free_space_check.hpp"
#include "scanfilter/implementation.hpp"
#include "scanfilter/mirror_ghost_check.hpp"
#include "scanfilter/obstacle_window.hpp"
#include "scanfilter/penetration_evidence.hpp"
#include "scanfilter/penetration_filter_params.hpp"
#include "scanfilter/penetration_grid.hpp"
#include "scanfilter/penetration_rule.hpp"
#include "scanfilter/range_image.hpp"
#include "scanfilter/scan.hpp"
#include "scanfilter/scan_geometry.hpp"
#include "scanfilter/sensor_info.hpp"
#include "scanfilter/surface_memory.hpp"
#include "scanfilter/thin_object_check.hpp"

namespace scanfilter {

// Step 2: the grid penetration model (paper section 4.2). A cache of recent
// frames votes into a grid; a point of the newest frame whose beam passes
// through an obstacle cell is a misdetection. The newest frame is judged
// against a grid it did not vote in, then joins the cache.
class PenetrationFilter {
 public:
  explicit PenetrationFilter(const PenetrationFilterParams& params);
  virtual ~PenetrationFilter() = default;
  // Its parts hold references to it (the rule, the evidence's test of a
  // surface's extent): a copy would judge with the original's.
  PenetrationFilter(const PenetrationFilter&) = delete;
  PenetrationFilter& operator=(const PenetrationFilter&) = delete;

  // `labels` holds step 1's codes; valid points found misdetected become
  // kMisdetected. Frames must come in stamp order.
  void apply(const Scan& scan, const SensorInfo& sensor, std::span<std::uint8_t> labels);

  // Judges `scan` against the current grid (aligned to it first, when
  // alignment is on) without changing any state: no cache update, no expiry,
  // no warm-up count, nothing remembered or forgotten. apply() is reset
  // check, the range noise measured (evidence_radius.hpp), expiry (of the
  // cache and of the surface memory, where the sensor drove through a
  // remembered surface too), judge(), remembering and caching: judge()
  // ignores expired surfaces but not driven-through ones.
  void judge(const Scan& scan, const SensorInfo& sensor, std::span<std::uint8_t> labels);

  // Forget every cached frame and start the warm-up again (the measured
  // range noise stays: it is the sensor's, not the cache's).
  void reset();

  const PenetrationGrid& grid() const { return grid_; }
  const SurfaceMemory& surfaceMemory() const { return memory_; }
  // The returns the rescue counts (rescue_persistent_points).
  const PenetrationGrid& rescueEvidence() const { return evidence_; }
  // The range noise measured for the evidence radius (zero until measured).
  RangeNoiseModel evidenceNoise() const { return evidence_radius_.noise(); }
  const PenetrationFilterParams& params() const { return params_; }
  std::size_t framesSinceReset() const { return frames_seen_; }
  std::size_t cachedFrames() const { return cache_.size(); }
  std::size_t resetCount() const { return resets_; }
  // Frames past the warm-up that did not fit the cache and so were not judged.
  std::size_t unalignedFrames() const { return unaligned_; }
  // Odometry pose -> cache frame: what the alignment has corrected so far.
  const Eigen::Isometry2d& poseCorrection() const { return correction_; }
  bool warmedUp() const { return frames_seen_ >= static_cast<std::size_t>(params_.min_frames); }

 protected:
  // Called once per judged frame, before markMisdetected(); points_ then
  // holds the frame's world points.
  virtual void prepareJudging(const Eigen::Vector2d& /*origin*/) {}
  // Marks kMisdetected every kValid point of points_ whose beam from `origin`
  // passes through an obstacle cell; cells within sqrt(ownMarginSq) of a
  // point are its own surface.
  virtual void markMisdetected(const Eigen::Vector2d& origin, std::span<std::uint8_t> labels) = 0;
  // Squared own-surface margin of point i seen from `origin`: the configured
  // margin, grown for a beam grazing its surface (grazing_margin). `length`
  // is (points_[i] - origin).norm(), for a caller that has it already.
  double ownMarginSq(const Eigen::Vector2d& origin, std::size_t i) const {
    return ownMarginSq(origin, i, (points_[i] - origin).norm());
  }
  double ownMarginSq(const Eigen::Vector2d& origin, std::size_t i, double length) const;
  // How far back from point i its beam stays within straddle_half_width of
  // the surface through i's neighbours (0 when they do not make one line).
  double grazingRun(const Eigen::Vector2d& origin, std::size_t i) const;
  // require_surface_extent's test of two obstacles across a beam (empty when
  // off): whether an obstacle that counts lies about a cell past either,
  // along the line through both.
  PenetrationEvidence::SurfaceGoesOn surfaceGoesOnTest(const PenetrationFilterParams& params);
  bool obstaclePastAlongLine(const Eigen::Vector2d& from, const Eigen::Vector2d& to) const;

  // The position q of an obstacle cell used by the rule: centre or centroid.
  Eigen::Vector2d obstaclePosition(CellIndex c) const {
    return params_.obstacle_at_centroid ? grid_.centroid(c) : grid_.cellCentre(c);
  }
  // Whether an obstacle at q can be evidence in the frame being judged:
  // not in the fringe of a surface end that frame sees (edge_smear_radius).
  bool countsAsObstacle(const Eigen::Vector2d& q) const { return !smear_zone_.contains(q); }
  // The judged frame's surface ends (edge_smear_radius; empty when off).
  const std::vector<Eigen::Vector2d>& surfaceEnds() const { return surface_ends_; }
  // How far q can lie from its cell's centre: widens the fast walk's band.
  double positionSlack() const { return params_.obstacle_at_centroid ? grid_.cellSize() * std::sqrt(0.5) : 0.0; }

  PenetrationFilterParams params_;
  PenetrationRule rule_;
  PenetrationEvidence evidence_along_beam_;
  // The obstacle votes: points the filter kept, and the lone returns the
  // free-space check marked (free_space_lone_returns_vote).
  PenetrationGrid grid_;
  PenetrationGrid evidence_;  // every return, kept or not: for the rescue
  // The votes (as grid_'s) of the frames in evidence_, while
  // countsKeptReturnsFromAfar(); empty otherwise.
  PenetrationGrid kept_from_afar_;
  std::vector<Eigen::Vector2d> points_;  // world points of the frame being judged

 private:
  struct CachedFrame {
    Stamp stamp;
    Eigen::Vector2d origin;  // the sensor's position (odometry)
    // Runs of grid_'s cells (evidence_ has the same cells), in scan order.
    std::vector<CellRun> votes;   // in grid_
    std::vector<CellRun> others;  // the other returns, in evidence_ only
    bool in_evidence = false;     // its returns are in evidence_ (rescue_min_baseline)
    std::optional<RangeImage> image;  // its ranges, for the free-space check (when on)
    Eigen::Vector2d placed_origin = Eigen::Vector2d::Zero();  // the sensor where the alignment put the frame
  };
  // Where a frame lies: points_ under the pose and the running correction;
  // returns the sensor origin there.
  Eigen::Vector2d placeFrame(const Scan& scan, const SensorInfo& sensor);
  // Beyond the paper 29: the surfaces the cache holds a return at a time
  // (sparse_surfaces.hpp), into the memory, seen from `origin`.
  void rememberSparseSurfaces(const Eigen::Vector2d& origin, Stamp stamp);
  // The cache's cells holding points within the bounds of this frame's
  // returns and its sensor.
  std::vector<CellMean> cellsInReach(const Eigen::Vector2d& origin) const;
  // Drops the sparse cells of the surfaces `found` that a cached frame saw
  // beyond a surface of `surfaces`; whether it dropped any.
  bool dropCellsSeenBeyond(const SurfaceMemory& surfaces, std::span<const StraightSegment> found, Stamp stamp,
                           std::vector<CellMean>& cells) const;
  struct Judgement {
    bool judged = false;
    Eigen::Isometry2d correction;  // the running correction after this frame
    Eigen::Vector2d origin = Eigen::Vector2d::Zero();  // the sensor, where the frame was judged from
  };
  Judgement alignAndJudge(const Scan& scan, const SensorInfo& sensor, std::span<std::uint8_t> labels);
  void judgePoints(const Eigen::Vector2d& origin, std::span<std::uint8_t> labels);
  // The judged frame's surface ends (points_ placed as judged), when
  // edge_smear_radius is on: returns with a neighbour beyond them by
  // edge_depth_step on one side, their surface running on on the other,
  // and nothing in the cache where it would go on past the end.
  void findSurfaceEnds(const Scan& scan);
  // The first return from i on in the direction `step` (+1 or -1) that lies
  // edge_smear_radius from return i, when the returns up to it run
  // unbroken (each within edge_depth_step of the last): the surface that
  // ends at i, seen a fringe's reach inside. nullopt when it breaks first.
  std::optional<Eigen::Vector2d> surfaceBehind(const Scan& scan, std::size_t i, std::ptrdiff_t step) const;
  // Whether the cache holds no obstacle where the surface through `inside`
  // and `end` would run on past the fringe's reach.
  bool cacheEndsToo(const Eigen::Vector2d& end, const Eigen::Vector2d& inside) const;
  // rescue_min_parallax_deg: a cached frame looking at p from aside ended at
  // it, or none looked from aside at all.
  bool hitFromAside(const Eigen::Vector2d& p, const Eigen::Vector2d& origin) const;
  void rescuePersistentPoints(const Eigen::Vector2d& origin, std::span<std::uint8_t> labels);
  // Returns of `grid` whose cells' means lie within the evidence radius of
  // p, seen from the sensor at `origin` (rescue_radius, or more for a noisy
  // sensor at p's range: evidence_radius.hpp).
  int countAround(const PenetrationGrid& grid, const Eigen::Vector2d& p, const Eigen::Vector2d& origin) const;
  // The rescue's evidence there: returns of every label, from the frames it admits.
  int evidenceAround(const Eigen::Vector2d& p, const Eigen::Vector2d& origin) const {
    return countAround(evidence_, p, origin);
  }
  // Whether the thin-object check asks kept returns of the frames the
  // rescue admits (Beyond the paper 38): only then is kept_from_afar_ kept.
  // Without a baseline every frame is admitted as it is cached, and grid_
  // holds the same votes.
  bool countsKeptReturnsFromAfar() const {
    return params_.thin_object_check && params_.thin_object_evidence_kept && params_.thin_object_kept_from_afar &&
           evidenceWaitsForBaseline();
  }
  // The cache's votes there (its kept returns, and the lone ones the
  // free-space check marked): from the frames the rescue
  // admits with thin_object_kept_from_afar, else from every cached frame.
  int keptReturnsAround(const Eigen::Vector2d& p, const Eigen::Vector2d& origin) const {
    return countAround(countsKeptReturnsFromAfar() ? kept_from_afar_ : grid_, p, origin);
  }
  // thin_object_check: whether returns from elsewhere say an object stands
  // at p (the rescue's evidence holds rescue_min_count returns, and with
  // thin_object_evidence_kept as many kept returns of the cache lie there).
  bool thinObjectStandsAt(const Eigen::Vector2d& p, const Eigen::Vector2d& origin) const;
  void resetOnPoseJump(const Eigen::Vector2d& origin, Stamp stamp);
  void dropOldestFrame();
  // Drops the cached frames older than T_max at `stamp`.
  void expireFrames(Stamp stamp);
  // Drops the oldest frames while the cache is full (max_cache_frames).
  void makeRoomForAFrame();
  // Whether a frame taken at `stamp` joins the cache (cache_min_interval).
  bool cachesFrameAt(Stamp stamp) const;
  void cacheFrame(const Scan& scan, const SensorInfo& sensor, const Eigen::Vector2d& origin,
                  std::span<const std::uint8_t> labels);
  // free_space_check: kept returns that far cached frames looked through
  // become jump points (points_ and `origin` placed as judged).
  void markSeenThrough(const Scan& scan, const Eigen::Vector2d& origin, std::span<std::uint8_t> labels);
  // Whether a return the check marked may be a pane's direct return, and
  // so votes in the cache (free_space_lone_returns_vote, 39 and 44).
  bool mayBeAPanesDirectReturn(const Eigen::Vector2d& origin, const Eigen::Vector2d& p, StandsInFront stands,
                               const Scan& scan) const;
  // Whether the beam from `origin` to p crossed a confirmed pane or mirror
  // of the surface memory where it is there (its stretch, 35's line test,
  // or free_space_lone_vote_pane_reach past the stretch), p beyond its line
  // by 35's minimum depth: p was seen through it or reflected by it (44).
  bool seenBeyondAPane(const Eigen::Vector2d& origin, const Eigen::Vector2d& p, Stamp stamp) const;
  // thin_object_check: kept returns standing in front of both sides with a
  // cached object in their footprint, in front of them, become jump points
  // (points_ and `origin` placed as judged); beside a beam without a return
  // (thin_object_beside_no_return) only with a second one behind them,
  // within `range_max` of the sensor.
  void markMixedReturnsOfThinObjects(const Scan& scan, const Eigen::Vector2d& origin, double range_max,
                                     std::span<std::uint8_t> labels) const;
  // Whether a cell holding thin_object_min_returns (outside the frame's edge fringes)
  // puts an object in the footprint of the beam from `origin` to p, in front
  // of p.
  bool objectInFootprint(const Eigen::Vector2d& origin, const Eigen::Vector2d& p, double angle_step) const;
  // Whether an obstacle cell (more than obs_th returns, outside the fringes)
  // lies in that footprint behind p, within `range_max` of the sensor (none
  // when range_max is not finite, or no farther than p).
  bool obstacleBehindInFootprint(const Eigen::Vector2d& origin, const Eigen::Vector2d& p, double angle_step,
                                 double range_max) const;
  // Which cells of grid_ the walks along a beam look at.
  enum class CellsThatCount { kThinObjectCells, kObstacles };
  // Whether such a cell, outside the fringes, within the footprint's box
  // from `from` to `to` along the beam from `origin` (unit direction), has a
  // position for which pred(position) holds.
  template <typename Pred>
  bool anyCellAlongBeam(const Eigen::Vector2d& origin, const Eigen::Vector2d& unit, double from, double to,
                        double angle_step, CellsThatCount cells, Pred&& pred) const;
  // surface_memory: kept returns beyond a remembered surface, and the
  // ghosts of remembered mirrors (mirror_ghosts_), become misdetected
  // (points_ and `origin` placed as judged); then, beyond a mirror the
  // frame found a ghost in, its other kept returns where it is there (43).
  // A return behind a remembered surface goes without the image test, but
  // takes it while its mirror is unproven: its ghost proves the mirror too.
  void markBeyondRememberedSurfaces(Stamp stamp, const Eigen::Vector2d& origin,
                                    std::span<std::uint8_t> labels) const;
  // The kept returns p (points_) with beyond(p) become misdetected.
  template <typename Beyond>
  void markKeptReturnsWhere(std::span<std::uint8_t> labels, Beyond&& beyond) const;
  // With rescue_min_baseline: the cached frames taken at least that far from
  // `origin` join the evidence; all of them while none is.
  void admitEvidence(const Eigen::Vector2d& origin);
  // All of a frame's returns into evidence_ (the rescue's), and its kept ones
  // into kept_from_afar_ (the thin-object check's), or out of them.
  void addRescueEvidence(const CachedFrame& frame);
  void removeRescueEvidence(const CachedFrame& frame);
  bool evidenceWaitsForBaseline() const {
    return params_.rescue_persistent_points && params_.rescue_min_baseline > 0.0;
  }
  // Beams either side of a return within edge_vote_margin_deg (0: off).
  int edgeHalfWidthBeams(const Scan& scan) const;

  std::deque<CachedFrame> cache_;
  BeamDirectionTable directions_;
  std::optional<Eigen::Vector2d> last_origin_;
  std::size_t frames_seen_ = 0;
  std::size_t resets_ = 0;
  FrameAligner aligner_;
  FreeSpaceCheck free_space_;
  // The judged frame's lone returns the free-space check marked, which vote
  // when it is cached (free_space_lone_returns_vote); empty when the check
  // did not run on this frame or the key is off.
  BeamMask lone_seen_through_;
  ThinObjectCheck thin_objects_;
  SurfaceMemory memory_;
  MirrorGhostCheck mirror_ghosts_;
  // Measured on every scan; kept across resets (the sensor's noise does not change with the cache).
  EvidenceRadius evidence_radius_;
  EdgeSmearZone smear_zone_;
  std::vector<Eigen::Vector2d> surface_ends_;  // the frame's ends: smear_zone_'s, and the fast walk's to erase
  // Odometry pose -> the cache's frame: the sum of the frames' alignments
  // since the last reset.
  Eigen::Isometry2d correction_ = Eigen::Isometry2d::Identity();
  std::size_t unaligned_ = 0;
};

// Steps a-f as printed: every point is tested against every obstacle cell.
class ReferencePenetrationFilter final : public PenetrationFilter {
 public:
  using PenetrationFilter::PenetrationFilter;

 private:
  void prepareJudging(const Eigen::Vector2d& origin) override;
  void markMisdetected(const Eigen::Vector2d& origin, std::span<std::uint8_t> labels) override;
  // True when the beam from sensor r to p passes through an obstacle cell.
  bool isMisdetected(const Eigen::Vector2d& r, const Eigen::Vector2d& p, double own_sq);
  std::vector<Eigen::Vector2d> obstacles_;
};

// Walks the beams through a dense snapshot of the obstacle cells within the
// frame's reach, visiting only the cells of a thick ray around them: the cost
// per point follows the beam's length, not the map. Neighbouring beams that
// fit one band are walked together (beam_bundle.hpp).
class FastPenetrationFilter final : public PenetrationFilter {
 public:
  using PenetrationFilter::PenetrationFilter;

 private:
  struct Beam {
    std::size_t index;  // into points_ and the labels
    double own_sq;
    BundledBeam walk;
  };
  void prepareJudging(const Eigen::Vector2d& origin) override;
  // Takes the fringes of the frame's surface ends out of window_
  // (countsAsObstacle, found from the ends).
  void eraseEdgeFringes();
  void markMisdetected(const Eigen::Vector2d& origin, std::span<std::uint8_t> labels) override;
  // The walk of point i's beam from `origin`; nullopt when no cell can be evidence.
  std::optional<Beam> beamOf(const Eigen::Vector2d& origin, std::size_t i) const;
  // Judges the beams in bundle_ with one walk and empties it.
  void judgeBundle(const Eigen::Vector2d& origin, std::span<std::uint8_t> labels);
  // The beam judged by its own walk.
  bool walkAlone(const Eigen::Vector2d& origin, const Beam& beam);
  // The beam judged against the bundle's cells, a superset of the obstacle
  // positions its own walk would visit.
  bool isMisdetected(const Eigen::Vector2d& origin, const Beam& beam);
  // Fills near_cell_indices_ with the bundle's cells within the rule's outer
  // half width of the beam (a superset of those test (c) keeps); how many.
  std::size_t keepCellsNearBeam(const Eigen::Vector2d& origin, const Beam& beam);
  // Cell position q as evidence against the beam (the shared rule); true once
  // the beam's evidence is conclusive.
  bool addBeamEvidence(const Eigen::Vector2d& origin, const Beam& beam, const Eigen::Vector2d& q);
  // Half width of one beam's walk: off the beam by the straddle (or
  // corridor) and by how far an obstacle's position can sit from its cell centre.
  double walkHalfWidth() const { return rule_.outerHalfWidth() + positionSlack(); }
  // How much wider than one beam's band a bundle's may grow, and how many
  // beams it may hold: past either, the cells a bundle visits and tests cost
  // more than the walks it saves (labels do not depend on them).
  double maxExtraBundleWidth() const { return walkHalfWidth(); }
  static constexpr std::size_t kMaxBundleBeams = 32;

  ObstacleWindow window_;
  std::vector<Beam> bundle_;
  std::vector<BundledBeam> bundle_walks_;  // bundle_[k].walk, contiguous for bundleBand; filled and emptied with it
  std::vector<Eigen::Vector2d> bundle_cells_;    // obstacle positions in the bundle's band
  std::vector<Eigen::Vector2d> bundle_offsets_;  // the same minus the origin, as the rule's w = q - r
  std::vector<std::uint32_t> near_cell_indices_;  // into bundle_cells_: keepCellsNearBeam's result
};

std::unique_ptr<PenetrationFilter> makePenetrationFilter(const PenetrationFilterParams& params,
                                                         Implementation impl);

}  // namespace scanfilter
