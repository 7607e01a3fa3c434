#pragma once
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "scanfilter/beam_mask.hpp"
#include "scanfilter/cell_bitmap.hpp"
#include "scanfilter/cell_slots.hpp"
#include "scanfilter/penetration_grid.hpp"

namespace scanfilter {

// Parameters of the frame alignment of step 2 (beyond the paper): before a
// frame is judged, it is fitted to the cached frames' obstacle cells, so that
// pose error (wheel odometry drifts) does not make its beams appear to pass
// through walls they in fact end on.
struct FrameAlignmentParams {
  bool enabled = true;
  int max_iterations = 8;
  // A point matches the nearest obstacle cell within this distance (m); it
  // bounds the pose error the alignment can take out per frame.
  double max_match_distance = 0.15;
  // The two neighbours that give a point its surface direction must be
  // within this distance of each other (m) and the point within
  // `max_off_line` of their line: otherwise it has no normal and no say.
  double max_neighbour_span = 0.3;
  double max_off_line = 0.02;
  // The fit is good, and the frame judged, when at least this share of the
  // points with a normal matched, at least `min_matches` of them, and their
  // RMS distance to the matched surfaces is at most `max_rms` (m).
  double min_matched_share = 0.5;
  int min_matches = 20;
  double max_rms = 0.03;
  // A correction is taken only if it brings the matched points at least this
  // much nearer their surfaces (RMS, m): with good poses the fit would
  // otherwise chase range noise and let the cache wander; a frame that
  // already fits keeps its pose.
  double min_rms_gain = 0.003;
  // At most this many points with a surface direction take part in the fit
  // (spread evenly over the scan when there are more; 0: all; else at least
  // min_matches, or no fit could be good). Three unknowns need few
  // points; beyond a few hundred they add cost (a 3,600-beam scan has ten
  // times those of a 360-beam one) but not accuracy.
  int max_fit_points = 480;
};


// A rigid correction of a frame (rotation about the sensor, then a shift)
// and how well the frame fitted after it.
struct FrameAlignment {
  Eigen::Isometry2d correction = Eigen::Isometry2d::Identity();
  bool good = false;
  int matches = 0;
  int candidates = 0;
  double rms = 0.0;
};

// Point-to-line ICP of one frame's world points onto the obstacle cells of
// the cache (their centroids): each point with a surface direction (from its
// scan neighbours) matches the nearest obstacle cell, and a Gauss-Newton step
// minimises the distances along the points' normals (a direction no surface
// constrains, along a corridor, is left as the odometry put it).
// Bounded iterations; deterministic, so both implementations of step 2 see
// the same correction.
class FrameAligner {
 public:
  explicit FrameAligner(const FrameAlignmentParams& params) : params_(params) {}

  // `points`: the frame's world points (NaN: no return); `usable[i]` false
  // for points that must not pull the fit (step 1's jump points).
  FrameAlignment align(const PenetrationGrid& grid, std::span<const Eigen::Vector2d> points,
                       const BeamMask& usable, const Eigen::Vector2d& origin);

 private:
  struct Match {
    Eigen::Vector2d point;   // in the frame, before the correction
    Eigen::Vector2d normal;  // unit, in the frame, before the correction
    Eigen::Vector2d target;  // the matched cell's centroid, in the world
  };
  void snapshotObstacles(const PenetrationGrid& grid, std::span<const Eigen::Vector2d> points);
  // The nearest obstacle centroid within max_match_distance of p (ties: the
  // last in row order), or none; `*unchanged_within` gets how far p may move
  // with the answer sure to stay the same (0 when nothing is sure).
  const Eigen::Vector2d* nearestObstacle(const Eigen::Vector2d& p, double* unchanged_within) const;
  // The cells within `reach` cells of p's: the nearest centroid within
  // max_match_distance (ties: the last in row order), the squared distance of
  // the nearest other one (with no answer: the nearest of all; infinity:
  // none), and how far p is from the edge of the block searched. The edge is
  // that of the whole block even where the window cuts it off: the snapshot
  // holds no obstacle outside the window.
  struct BlockSearch {
    const Eigen::Vector2d* best = nullptr;
    double best_sq = 0.0;
    double runner_up_sq = std::numeric_limits<double>::infinity();
    double edge = 0.0;
  };
  BlockSearch searchBlock(const Eigen::Vector2d& p, int reach) const;
  void findNormals(std::span<const Eigen::Vector2d> points, const BeamMask& usable);
  // Keeps max_fit_points of the points with a direction, spread evenly.
  void thinToMaxFitPoints();
  int matchPoints(const Eigen::Isometry2d& correction);
  // Gauss-Newton from no correction until it converges or max_iterations;
  // matches_ already holds the matches of no correction (align made them).
  Eigen::Isometry2d fit(const Eigen::Vector2d& origin);
  // One Gauss-Newton step of the point-to-line distances.
  Eigen::Isometry2d step(const Eigen::Isometry2d& correction, const Eigen::Vector2d& origin) const;
  double rms(const Eigen::Isometry2d& correction) const;

  FrameAlignmentParams params_;
  // Obstacle cells over the frame's reach: per cell an index into
  // centroids_ (CellSlots::kNone: none), rebuilt every frame, mostly empty.
  CellSlots cells_;
  // The same cells as one bit each, a row of words per cell row: a point's
  // neighbourhood (7 x 7 cells at the defaults) is read as 7 short bit runs,
  // and only the set bits cost a look at cells_ (at 3,600 beams the scan of
  // empty cells was a third of step 2's time).
  CellBitmap occupied_bits_;
  std::vector<Eigen::Vector2d> centroids_;
  CellIndex lo_;
  int width_ = 0;
  int height_ = 0;
  double cell_size_ = 0.0;
  std::vector<Eigen::Vector2d> with_normal_points_;
  std::vector<Eigen::Vector2d> normals_;
  std::vector<Match> matches_;
  // Per point with a normal, its last query: where, the answer, and how far
  // from there the answer holds. The Gauss-Newton steps move the points by
  // millimetres, so most matchings repeat the last answer without a search.
  struct LastQuery {
    Eigen::Vector2d at;
    const Eigen::Vector2d* nearest;
    double unchanged_within;  // negative: no query yet
  };
  std::vector<LastQuery> last_queries_;
};

}  // namespace scanfilter
