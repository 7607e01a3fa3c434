#pragma once
#include <cstddef>

#include "scanfilter/frame_alignment.hpp"
#include "scanfilter/range_noise_sampling.hpp"
#include "scanfilter/surface_memory.hpp"

namespace scanfilter {

// Parameters of step 2, the grid penetration model (paper section 4.2).
// Defaults are the values chosen by the sweep in docs/accuracy.md;
// config/filter.yaml documents every key and gives the paper-literal preset.
struct PenetrationFilterParams {
  double cell_size = 0.05;          // m, W_g
  double frame_lifetime = 4.0;      // s, T_max: cached frames older than this leave
  int min_frames = 5;               // F_Lmin: frames seen before anything is judged
  int obstacle_threshold = 2;       // obs_th: a cell counting more points is an obstacle
  double corridor_half_width = 0.015;  // m, step (c): cells farther off the beam are ignored
  // Where an obstacle cell is: the paper's q_n is the cell centre; the mean of
  // the points it counted puts a thin leg or an edge where it really is.
  bool obstacle_at_centroid = true;
  // Beyond the paper: a beam that really passes through a surface passes
  // between neighbouring cells of it, one on each side; one passing beside an
  // edge, a door jamb or a leg (within the pose error) has them on one side
  // only. When true, a point is misdetected only if two penetrating cells
  // within `straddle_half_width` of the beam, on opposite sides, lie at most
  // `surface_gap` apart; the corridor then plays no part.
  bool require_both_sides = true;
  double straddle_half_width = 0.075;  // m
  double surface_gap = 0.06;          // m
  // Beyond the paper: with require_both_sides, the two cells count only when
  // an obstacle goes on past one of them along the line through both (about
  // a cell farther): a surface, not the compact blob a thin leg's cached
  // returns make, which range noise, mixing and the footprint spread across
  // the beams that pass within a few centimetres of the leg.
  bool require_surface_extent = true;
  double own_surface_margin = 0.25;    // m, cells nearer the point are its own surface
  double own_surface_margin_per_m = 0.02;  // m per m of range added to that margin
  // Beyond the paper: a beam meeting its surface at a grazing angle g runs
  // within straddle_half_width of that surface for straddle_half_width / tan g
  // before it ends, so the cells it passes there are its own surface, not a
  // wall it penetrates. The own-surface margin grows to that length (at most
  // grazing_margin_max), the surface's direction taken from the neighbouring
  // returns when they lie on one line with the point.
  bool grazing_margin = true;
  double grazing_margin_max = 1.0;  // m
  double behind_margin = 0.0;       // m, step (e) read literally: cells this near beyond p mark it
  double pose_jump_reset = 0.5;     // m, a larger sensor jump between frames resets the cache
  std::size_t max_cache_frames = 40;  // bound on cached frames whatever T_max says: obs_th counts over them (config/filter.yaml)
  // Beyond the paper: a frame taken sooner than this after the last cached
  // one is judged but not cached. At 25-40 Hz the 40 cached frames would
  // span 1-1.6 s of nearly one viewpoint; every second frame spans twice
  // that, and caching costs half (docs/beyond-the-paper.md, 21).
  // 45 ms lies at least 5 ms from one, two or three periods of the common
  // rates (10, 12.5, 15, 20, 25, 30, 40, 50 Hz), so stamp jitter below that
  // does not change which frames are cached. 0: every frame (the paper).
  // A frame whose stamp is not later than the last cached one's is cached:
  // such stamps are no clock.
  double cache_min_interval = 0.045;  // s
  bool cache_misdetected_points = false;  // misdetected points vote in later grids
  // Beyond the paper (depth_edges.hpp): returns within this angle (at least
  // one beam) of a kept return more than `edge_depth_step` farther do not
  // vote: at an edge they are mixed returns that smear it outwards. 0: every
  // return votes (the default: on the simulator it costs ghost recall).
  double edge_vote_margin_deg = 0.0;  // degrees
  double edge_depth_step = 0.15;      // m
  // Beyond the paper (docs/beyond-the-paper.md, 22): where the judged frame sees a
  // surface end (a return with a neighbour farther by edge_depth_step on one
  // side and its surface running on unbroken for this distance on the
  // other), the obstacle cells within this distance of it are not evidence,
  // unless the cache holds obstacles on beyond them (a pane or mirror seen
  // only in places): cached returns fringe a surface's end by several
  // centimetres (footprints straddling it, pose error), and a beam just
  // beside the end would seem to cross the surface. 0: off (the paper).
  double edge_smear_radius = 0.15;  // m
  // Beyond the paper (grazing_returns.hpp; docs/beyond-the-paper.md, 23): returns
  // whose beam meets their surface at less than this angle do not vote:
  // displaced along a surface seen at grazing incidence, they fringe it, and
  // beams running beside it seem to cross it. 0: every return votes (the
  // default: on the simulator it costs ghost recall, as 15 does).
  double grazing_vote_max_deg = 0.0;  // degrees
  // Beyond the paper (docs/beyond-the-paper.md, 1): step 1 deletes every
  // cluster of one or two beams, so a thin leg is always lost. A jump point
  // is restored when the cached frames put at least `rescue_min_count`
  // returns in its cell:
  // persistent evidence that a jump point, which moves with the viewpoint,
  // does not leave. Off reproduces the paper.
  bool rescue_persistent_points = true;
  int rescue_min_count = 5;
  // Evidence counts the cached returns of the cells whose centroid lies within
  // this distance of the point: a thin leg's returns pile up within a few cm,
  // a jump point lies off every surface by more than that. The radius grows
  // where the measured range noise is larger (below); "within
  // rescue_radius" in these comments means within that grown radius.
  double rescue_radius = 0.08;  // m
  // Beyond the paper 33 (evidence_radius.hpp): the radius grows to this many
  // σ(range) of the range noise step 2 measures on the scans (as step 1
  // does, but the measured model alone, with no configured floor), σ at the
  // point's distance from the sensor: a noisy sensor's returns of one
  // surface scatter farther than rescue_radius. Every count within
  // rescue_radius (the rescue, the free-space veto, the thin-object check's
  // spare) uses it. 0: rescue_radius at every range.
  double evidence_noise_sigmas = 5.0;
  // ... up to this (m): farther, the counts would reach across the depth
  // edges the checks look at (edge_depth_step) and visit many more cells.
  // Below rescue_radius it changes nothing.
  double evidence_radius_max = 0.30;
  // How step 2 samples the scans for it: window_scans is
  // evidence_noise_window_scans (step 2 keeps state anyway, and one scan's
  // estimate swings from scan to scan); min_samples is step 1's
  // noise_estimate_min_samples, copied by FilterConfig::resolve.
  RangeNoiseSampling evidence_noise_sampling{.window_scans = 20.0};
  // Evidence counts only the cached frames seen from at least this far from
  // where the point is seen now (sensor origins, m): a real surface is hit
  // again from elsewhere, a mixed return or a displaced one follows the
  // viewpoint, and a fast scanner's last frames share nearly one viewpoint.
  // A frame joins the evidence once the sensor is this far from where it
  // was taken. While no cached frame is (a robot standing still, turning on
  // the spot or creeping, and the first metres after a start or a cache
  // reset), every cached frame counts: without parallax nothing tells a thin
  // leg from a mixed return, and both are kept, as without the baseline. A
  // frame that joined stays until it expires, also when the robot comes
  // back to where it was taken. 0: every cached frame counts at once.
  double rescue_min_baseline = 0.25;  // m
  // Beyond the paper 36: a mixed return stays put while the sensor moves
  // along its beam (the edge and the background it mixes come nearer
  // together), so frames taken along that line vouch for it as a surface;
  // seen from aside it lands elsewhere. So the rescue also needs one cached
  // frame whose beam towards the point meets the current beam at this angle
  // or more to have ended at it (free_space_check.hpp's hit), whenever such
  // a frame looked that way at all (one that saw nothing there, or only the
  // fringe of an edge, does not count). Frames are cached with their ranges
  // only with free_space_check on; without them this test passes. 0: off.
  double rescue_min_parallax_deg = 5.0;  // degrees
  // Beyond the paper (free_space_check.hpp): a kept return beside a depth
  // edge becomes a jump point when cached frames taken from at least
  // rescue_min_baseline away looked through where it lies (the four beams
  // around its bearing went on beyond it by free_space_margin) more often
  // than they ended at it, and such frames put fewer than
  // free_space_veto_count returns within rescue_radius of it: a mixed or
  // displaced return in free space, which eq. 5 joined to a surface's
  // cluster or which stands in front of both sides like a thin leg. The
  // depth edge is edge_depth_step. false = the paper.
  bool free_space_check = true;
  double free_space_margin = 0.10;  // m
  // m per m of the point's distance from the cached frame's sensor, added
  // to the margin: range noise and the pose error left after alignment both
  // move a far return more (docs/beyond-the-paper.md, 20).
  double free_space_margin_per_m = 0.01;
  double free_space_dip = 0.05;     // m, a bracketing beam this much short of the outer ones does not count
  int free_space_min_frames = 1;
  // Returns from elsewhere (the rescue's evidence, so only with
  // rescue_persistent_points; of one frame or several) that vouch for a
  // surface there. One was enough until it was measured: the mixed returns
  // of a thin leg, seen from other places, scatter behind it, and one of
  // them near another was vetoing the check for most of them
  // (docs/beyond-the-paper.md, 19). The count the filter uses:
  // config/filter.yaml gives it for 1° steps and FilterConfig::resolve
  // scales it to the sensor's.
  int free_space_veto_count = 2;
  // Beyond the paper 39: a lone return (one beam in front of both sides by
  // edge_depth_step) that the check marks still votes in the cache. Other
  // viewpoints look through glass and past a mirror (its light goes
  // elsewhere), so the check cannot tell a pane's or a mirror's occasional
  // direct return from a thin leg's mixed one; but a pane's pile up on its
  // line frame after frame, where mixed returns move with the viewpoint and
  // seldom reach obs_th in one cell. Without their votes the cache never
  // holds the pane, and step 2 never finds what lies behind it. A marked
  // return beside one depth edge (mixed at an edge) does not vote:
  // measured, those votes cost the Mines logs their selectivity; nor one
  // beside a beam without a return (the mix of two objects, 30), nor one
  // with a cached object in its footprint in front of it (that object's
  // mixed return: the thin-object check's test, 25): measured, more valid
  // returns went (docs/beyond-the-paper.md, 39). A lone vote is a
  // vote like a kept return's, also for the thin-object check's kept
  // returns (31; kept out of them, measured, more valid returns went). With
  // edge_vote_margin_deg > 0 no lone return votes: it lies beside a depth
  // edge. false: no marked return votes (until 39).
  bool free_space_lone_returns_vote = true;
  // Beyond the paper 44: with free_space_lone_returns_vote, a lone return
  // whose beam crossed the line of a confirmed pane or mirror first (the
  // surface memory's, 34), and lies beyond it as far as 35 asks of a ghost,
  // does not vote: it was seen through that pane or reflected by it. A
  // ghost lies on the image of the wall it came from, so its votes line up
  // into a sparse surface (29) that is no surface, and the memory then
  // takes the real wall behind it for seconds. The pane is there on its
  // remembered stretch, where 35's line test finds it, and up to
  // free_space_lone_vote_pane_reach past the stretch's ends
  // (MirrorGhostCheck::mirrorWithin). true: such returns vote too, as
  // with 39 alone.
  bool free_space_lone_votes_beyond_panes = false;
  // m past the remembered stretch a crossing still counts as on the pane, 0-10.
  double free_space_lone_vote_pane_reach = 0.30;
  // Beyond the paper (thin_object_check.hpp; docs/beyond-the-paper.md, 25):
  // a kept return in a stretch of at most thin_object_max_beams returns
  // standing in front of both sides (by thin_object_depth_step; the
  // object's own returns and its mixed ones beside them) becomes a jump point
  // when a cell holding thin_object_min_returns cached returns lies on its
  // beam more than thin_object_depth_step in front of it, within
  // thin_object_radius of the beam's footprint (one angular step wide): the
  // mixed return of an object thinner than the footprint. Not when the
  // rescue would restore it (rescue_min_count returns from elsewhere within
  // rescue_radius: an object there). false = the paper.
  bool thin_object_check = true;
  int thin_object_max_beams = 3;
  double thin_object_radius = 0.02;  // m
  // Beyond the paper 37: the check's own depth step (edge_depth_step until
  // 37). A leg's mixed return lies anywhere between the leg and the wall
  // behind it, and the leg's cached position is the mean of returns that
  // include its mixes, pulled back towards them: 15 cm missed the mixes
  // that land nearest the leg.
  double thin_object_depth_step = 0.12;  // m
  // Beyond the paper 32: the returns a cached cell must hold to be that
  // object (obs_th until 32): a leg thinner than the footprint gives few
  // returns on itself. The count the filter uses: config/filter.yaml gives it
  // for obstacle_threshold_reference_deg and FilterConfig::resolve scales it
  // to the sensor's step, as obs_th.
  int thin_object_min_returns = 1;
  // Beyond the paper 30: a stretch beside a beam without a return counts
  // too, when a second cached object (an obstacle cell: more than obs_th
  // returns) lies in the footprint behind the return (within the sensor's
  // range): with no background within range there, a mixed return is a mix
  // of two objects, a chair's front and rear legs. false: such stretches are
  // never marked.
  bool thin_object_beside_no_return = true;
  // Beyond the paper 31: besides the rescue's evidence, the cache's votes
  // (the returns its frames kept, judged or still warming up; of every
  // cached frame, near or far, with thin_object_kept_from_afar false) must
  // hold rescue_min_count returns within rescue_radius to spare a return in
  // the thin-object check: other frames' mixed returns of a leg land there
  // too, but were mostly removed in their own frames. What votes also
  // follows edge_vote_margin_deg, grazing_vote_max_deg,
  // cache_misdetected_points and free_space_lone_returns_vote. false: the
  // rescue's evidence alone (returns of every label).
  bool thin_object_evidence_kept = true;
  // Beyond the paper 38: those kept returns count only from the frames the
  // rescue's evidence holds (with rescue_min_baseline, the frames that joined
  // once the sensor was that far from where they were taken): a mixed return
  // stays near where the same leg's mixes were seen from nearly the same
  // place, and those frames kept theirs for the same reason; from elsewhere
  // they land elsewhere. false: every cached frame's kept returns (31).
  bool thin_object_kept_from_afar = true;
  // Beyond the paper: each frame is fitted to the cache before it is judged
  // (frame_alignment.hpp); a frame that does not fit is not judged.
  FrameAlignmentParams alignment;
  // Beyond the paper (surface_memory.hpp): straight surfaces that judged
  // frames saw well are remembered for longer than the cache, and a kept
  // return beyond one is misdetected. lifetime 0: off (the paper).
  SurfaceMemoryParams surface_memory;
};

}  // namespace scanfilter
