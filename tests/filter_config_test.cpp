#include <chrono>

#include <gtest/gtest.h>

#include "scanfilter/filter_config.hpp"
#include "scanfilter/input_error.hpp"

namespace scanfilter {
namespace {

std::string errorOf(const std::string& yaml) {
  try {
    parseFilterConfig(yaml, "f.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(FilterConfig, ShippedConfigEqualsTheBuiltInDefaults) {
  const FilterConfig shipped = loadFilterConfig(SCANFILTER_SOURCE_DIR "/config/filter.yaml");
  const TwoStepFilterParams d;
  const auto& s = shipped.params;
  EXPECT_EQ(s.jump.alpha, d.jump.alpha);
  EXPECT_EQ(s.jump.theta_k_deg, d.jump.theta_k_deg);
  EXPECT_EQ(s.jump.l_min, d.jump.l_min);
  EXPECT_EQ(s.jump.l_max, d.jump.l_max);
  EXPECT_EQ(s.penetration.cell_size, d.penetration.cell_size);
  EXPECT_EQ(s.penetration.frame_lifetime, d.penetration.frame_lifetime);
  EXPECT_EQ(s.penetration.min_frames, d.penetration.min_frames);
  EXPECT_EQ(s.penetration.obstacle_threshold, d.penetration.obstacle_threshold);
  EXPECT_EQ(s.penetration.corridor_half_width, d.penetration.corridor_half_width);
  EXPECT_EQ(s.penetration.obstacle_at_centroid, d.penetration.obstacle_at_centroid);
  EXPECT_EQ(s.penetration.require_both_sides, d.penetration.require_both_sides);
  EXPECT_EQ(s.penetration.straddle_half_width, d.penetration.straddle_half_width);
  EXPECT_EQ(s.penetration.surface_gap, d.penetration.surface_gap);
  EXPECT_EQ(s.penetration.require_surface_extent, d.penetration.require_surface_extent);
  EXPECT_EQ(s.penetration.behind_margin, d.penetration.behind_margin);
  EXPECT_EQ(s.penetration.pose_jump_reset, d.penetration.pose_jump_reset);
  EXPECT_EQ(s.penetration.max_cache_frames, d.penetration.max_cache_frames);
  EXPECT_EQ(s.penetration.cache_min_interval, d.penetration.cache_min_interval);
  EXPECT_EQ(s.penetration.cache_misdetected_points, d.penetration.cache_misdetected_points);
  EXPECT_EQ(s.jump.span_range, d.jump.span_range);
  EXPECT_EQ(s.jump.straight_run_max_incidence_deg, d.jump.straight_run_max_incidence_deg);
  EXPECT_EQ(s.jump.keep_foreground_clusters, d.jump.keep_foreground_clusters);
  EXPECT_EQ(s.jump.keep_unresolved_returns, d.jump.keep_unresolved_returns);
  EXPECT_EQ(s.jump_enabled, d.jump_enabled);
  EXPECT_EQ(s.penetration_enabled, d.penetration_enabled);
  EXPECT_EQ(s.penetration.own_surface_margin, d.penetration.own_surface_margin);
  EXPECT_EQ(s.penetration.own_surface_margin_per_m, d.penetration.own_surface_margin_per_m);
  EXPECT_EQ(s.penetration.rescue_persistent_points, d.penetration.rescue_persistent_points);
  EXPECT_EQ(s.penetration.rescue_min_count, d.penetration.rescue_min_count);
  EXPECT_EQ(s.penetration.rescue_radius, d.penetration.rescue_radius);
  EXPECT_EQ(s.penetration.evidence_noise_sigmas, d.penetration.evidence_noise_sigmas);
  EXPECT_EQ(s.penetration.evidence_radius_max, d.penetration.evidence_radius_max);
  EXPECT_EQ(s.penetration.evidence_noise_sampling.window_scans, d.penetration.evidence_noise_sampling.window_scans);
  EXPECT_EQ(s.penetration.evidence_noise_sampling.min_samples, d.penetration.evidence_noise_sampling.min_samples);
  EXPECT_EQ(s.penetration.edge_vote_margin_deg, d.penetration.edge_vote_margin_deg);
  EXPECT_EQ(s.penetration.edge_depth_step, d.penetration.edge_depth_step);
  EXPECT_EQ(s.penetration.rescue_min_parallax_deg, d.penetration.rescue_min_parallax_deg);
  EXPECT_EQ(s.penetration.free_space_check, d.penetration.free_space_check);
  EXPECT_EQ(s.penetration.free_space_margin, d.penetration.free_space_margin);
  EXPECT_EQ(s.penetration.free_space_dip, d.penetration.free_space_dip);
  EXPECT_EQ(s.penetration.free_space_min_frames, d.penetration.free_space_min_frames);
  EXPECT_EQ(s.penetration.free_space_veto_count, d.penetration.free_space_veto_count);
  EXPECT_EQ(s.penetration.free_space_lone_returns_vote, d.penetration.free_space_lone_returns_vote);
  EXPECT_EQ(s.penetration.free_space_lone_votes_beyond_panes, d.penetration.free_space_lone_votes_beyond_panes);
  EXPECT_EQ(s.penetration.free_space_lone_vote_pane_reach, d.penetration.free_space_lone_vote_pane_reach);
  EXPECT_EQ(s.penetration.thin_object_check, d.penetration.thin_object_check);
  EXPECT_EQ(s.penetration.thin_object_max_beams, d.penetration.thin_object_max_beams);
  EXPECT_EQ(s.penetration.thin_object_radius, d.penetration.thin_object_radius);
  EXPECT_EQ(s.penetration.thin_object_depth_step, d.penetration.thin_object_depth_step);
  EXPECT_EQ(s.penetration.thin_object_min_returns, d.penetration.thin_object_min_returns);
  EXPECT_EQ(s.penetration.thin_object_beside_no_return, d.penetration.thin_object_beside_no_return);
  EXPECT_EQ(s.penetration.thin_object_evidence_kept, d.penetration.thin_object_evidence_kept);
  EXPECT_EQ(s.penetration.thin_object_kept_from_afar, d.penetration.thin_object_kept_from_afar);
  EXPECT_EQ(s.penetration.free_space_margin_per_m, d.penetration.free_space_margin_per_m);
  EXPECT_EQ(s.jump.noise_estimate, d.jump.noise_estimate);
  EXPECT_EQ(s.jump.noise_sampling.window_scans, d.jump.noise_sampling.window_scans);
  EXPECT_EQ(s.jump.noise_sampling.min_samples, d.jump.noise_sampling.min_samples);
  EXPECT_EQ(s.penetration.alignment.max_fit_points, d.penetration.alignment.max_fit_points);
  const SurfaceMemoryParams& sm = s.penetration.surface_memory;
  const SurfaceMemoryParams& dm = d.penetration.surface_memory;
  EXPECT_EQ(sm.lifetime, dm.lifetime);
  EXPECT_EQ(sm.min_interval, dm.min_interval);
  EXPECT_EQ(sm.min_beam_surface_angle_deg, dm.min_beam_surface_angle_deg);
  EXPECT_EQ(sm.surface_margin, dm.surface_margin);
  EXPECT_EQ(sm.surface_margin_per_m, dm.surface_margin_per_m);
  EXPECT_EQ(sm.end_margin, dm.end_margin);
  EXPECT_EQ(sm.merge_angle_deg, dm.merge_angle_deg);
  EXPECT_EQ(sm.merge_offset, dm.merge_offset);
  EXPECT_EQ(sm.max_segments, dm.max_segments);
  EXPECT_EQ(sm.head_on_deg, dm.head_on_deg);
  EXPECT_EQ(sm.head_on_through_beams, dm.head_on_through_beams);
  EXPECT_EQ(sm.specular_lifetime, dm.specular_lifetime);
  EXPECT_EQ(sm.sparse_lifetime, dm.sparse_lifetime);
  EXPECT_EQ(sm.specular_confirm_distance, dm.specular_confirm_distance);
  EXPECT_EQ(sm.drift_margin_per_m, dm.drift_margin_per_m);
  EXPECT_EQ(sm.drift_margin_deg_per_m, dm.drift_margin_deg_per_m);
  EXPECT_EQ(sm.specular_min_pass_share, dm.specular_min_pass_share);
  EXPECT_EQ(sm.mirror_ghosts.enabled, dm.mirror_ghosts.enabled);
  EXPECT_EQ(sm.mirror_ghosts.image_radius, dm.mirror_ghosts.image_radius);
  EXPECT_EQ(sm.mirror_ghosts.line_window, dm.mirror_ghosts.line_window);
  EXPECT_EQ(sm.mirror_ghosts.line_tolerance, dm.mirror_ghosts.line_tolerance);
  EXPECT_EQ(sm.mirror_ghosts.line_spread, dm.mirror_ghosts.line_spread);
  EXPECT_EQ(sm.mirror_ghosts.crossing_band, dm.mirror_ghosts.crossing_band);
  EXPECT_EQ(sm.mirror_ghosts.beyond_proven_mirrors, dm.mirror_ghosts.beyond_proven_mirrors);
  EXPECT_EQ(sm.segments.max_spacing, dm.segments.max_spacing);
  EXPECT_EQ(sm.segments.max_deviation, dm.segments.max_deviation);
  EXPECT_EQ(sm.segments.min_returns, dm.segments.min_returns);
  EXPECT_EQ(sm.segments.min_length, dm.segments.min_length);
  EXPECT_EQ(sm.segments.end_step, dm.segments.end_step);
  EXPECT_EQ(sm.segments.max_gap, dm.segments.max_gap);
  const SparseSurfaceParams& ss = sm.sparse_surfaces;
  const SparseSurfaceParams& ds = dm.sparse_surfaces;
  EXPECT_EQ(ss.enabled, ds.enabled);
  EXPECT_EQ(ss.min_beam_surface_angle_deg, ds.min_beam_surface_angle_deg);
  EXPECT_EQ(ss.neighbour_radius, ds.neighbour_radius);
  EXPECT_EQ(ss.min_neighbours, ds.min_neighbours);
  EXPECT_EQ(ss.max_thickness, ds.max_thickness);
  EXPECT_EQ(ss.max_thickness_noise_sigmas, ds.max_thickness_noise_sigmas);
  EXPECT_EQ(ss.max_thickness_ceiling, ds.max_thickness_ceiling);
  EXPECT_EQ(ss.max_angle_deg, ds.max_angle_deg);
  EXPECT_EQ(ss.max_gap, ds.max_gap);
  EXPECT_EQ(ss.max_deviation, ds.max_deviation);
  EXPECT_EQ(ss.max_deviation_noise_sigmas, ds.max_deviation_noise_sigmas);
  EXPECT_EQ(ss.max_deviation_ceiling, ds.max_deviation_ceiling);
  EXPECT_EQ(ss.min_cells, ds.min_cells);
  EXPECT_EQ(ss.min_length, ds.min_length);
  EXPECT_FALSE(shipped.angular_accuracy_deg) << "auto: from the sensor";
  const FilterConfig built_in;
  EXPECT_EQ(shipped.obstacle_threshold_reference_deg, built_in.obstacle_threshold_reference_deg);
  EXPECT_EQ(shipped.free_space_veto_reference_deg, built_in.free_space_veto_reference_deg);
  EXPECT_EQ(shipped.sparse_support_reference_deg, built_in.sparse_support_reference_deg);
}

TEST(FilterConfig, PaperLiteralPresetLoads) {
  const FilterConfig paper = loadFilterConfig(SCANFILTER_SOURCE_DIR "/config/filter-paper-literal.yaml");
  EXPECT_DOUBLE_EQ(paper.params.penetration.corridor_half_width, 0.1);
  EXPECT_DOUBLE_EQ(paper.params.penetration.behind_margin, 0.1);
  EXPECT_FALSE(paper.params.penetration.rescue_persistent_points);
  EXPECT_FALSE(paper.params.penetration.free_space_check);
  EXPECT_FALSE(paper.params.penetration.thin_object_check);
  EXPECT_FALSE(paper.params.penetration.require_surface_extent);
  EXPECT_EQ(paper.params.penetration.surface_memory.lifetime, 0.0) << "no memory beyond T_max";
  EXPECT_FALSE(paper.params.jump.noise_estimate) << "the paper has no noise model";
  EXPECT_FALSE(paper.params.jump.keep_foreground_clusters) << "eq. 7 as printed deletes every lone return";
  EXPECT_FALSE(paper.params.jump.keep_unresolved_returns);
}

TEST(FilterConfig, ReadsThePaneAndMirrorMemoryKeys) {
  const FilterConfig c = parseFilterConfig(
      "penetration_filter:\n  surface_memory:\n    specular_lifetime: 120\n    specular_confirm_distance: 0.2\n"
      "    drift_margin_per_m: 0.01\n    drift_margin_deg_per_m: 0.5\n    sparse_lifetime: 7.5\n",
      "f.yaml");
  const SurfaceMemoryParams& m = c.params.penetration.surface_memory;
  EXPECT_EQ(m.specular_lifetime, 120.0);
  EXPECT_EQ(m.sparse_lifetime, 7.5);
  EXPECT_NE(SurfaceMemoryParams{}.sparse_lifetime, 7.5);
  EXPECT_EQ(m.specular_confirm_distance, 0.2);
  EXPECT_EQ(m.drift_margin_per_m, 0.01);
  EXPECT_EQ(m.drift_margin_deg_per_m, 0.5);
}

TEST(FilterConfig, ReadsTheMirrorGhostKeys) {
  const FilterConfig c = parseFilterConfig(
      "penetration_filter:\n  surface_memory:\n    specular_min_pass_share: 0.7\n    mirror_ghosts:\n"
      "      enabled: false\n      image_radius: 0.05\n      line_window: 0.4\n      line_tolerance: 0.03\n"
      "      line_spread: 0.2\n      crossing_band: 0.15\n      beyond_proven_mirrors: false\n",
      "f.yaml");
  const SurfaceMemoryParams& m = c.params.penetration.surface_memory;
  EXPECT_EQ(m.specular_min_pass_share, 0.7);
  EXPECT_FALSE(m.mirror_ghosts.enabled);
  EXPECT_EQ(m.mirror_ghosts.image_radius, 0.05);
  EXPECT_EQ(m.mirror_ghosts.line_window, 0.4);
  EXPECT_EQ(m.mirror_ghosts.line_tolerance, 0.03);
  EXPECT_EQ(m.mirror_ghosts.line_spread, 0.2);
  EXPECT_EQ(m.mirror_ghosts.crossing_band, 0.15);
  EXPECT_FALSE(m.mirror_ghosts.beyond_proven_mirrors);
}

TEST(FilterConfig, ReadsTheThinObjectDepthStep) {
  const FilterConfig c = parseFilterConfig("penetration_filter:\n  thin_object_depth_step: 0.2\n", "f.yaml");
  EXPECT_EQ(c.params.penetration.thin_object_depth_step, 0.2);
  EXPECT_EQ(c.params.penetration.edge_depth_step, PenetrationFilterParams{}.edge_depth_step) << "its own key";
}

TEST(FilterConfig, ReadsWhereTheThinObjectChecksKeptReturnsCount) {
  const FilterConfig c = parseFilterConfig("penetration_filter:\n  thin_object_kept_from_afar: false\n", "f.yaml");
  EXPECT_FALSE(c.params.penetration.thin_object_kept_from_afar);
  EXPECT_TRUE(PenetrationFilterParams{}.thin_object_kept_from_afar);
}

TEST(FilterConfig, ReadsWhetherTheFreeSpaceChecksLoneReturnsVote) {
  const FilterConfig c = parseFilterConfig("penetration_filter:\n  free_space_lone_returns_vote: false\n", "f.yaml");
  EXPECT_FALSE(c.params.penetration.free_space_lone_returns_vote);
  EXPECT_TRUE(PenetrationFilterParams{}.free_space_lone_returns_vote);
}

TEST(FilterConfig, ReadsWhetherLoneReturnsBeyondAPaneVote) {
  const FilterConfig c = parseFilterConfig(
      "penetration_filter:\n  free_space_lone_votes_beyond_panes: true\n  free_space_lone_vote_pane_reach: 0.5\n",
      "f.yaml");
  EXPECT_TRUE(c.params.penetration.free_space_lone_votes_beyond_panes);
  EXPECT_EQ(c.params.penetration.free_space_lone_vote_pane_reach, 0.5);
  EXPECT_FALSE(PenetrationFilterParams{}.free_space_lone_votes_beyond_panes);
}

TEST(FilterConfig, ReadsTheRescueParallax) {
  const FilterConfig c = parseFilterConfig("penetration_filter:\n  rescue_min_parallax_deg: 12.5\n", "f.yaml");
  EXPECT_EQ(c.params.penetration.rescue_min_parallax_deg, 12.5);
}

TEST(FilterConfig, AutoValuesComeFromTheSensor) {
  const FilterConfig c = parseFilterConfig("jump_filter:\n  d_max: auto\n  angular_accuracy_deg: 0.5\n", "f.yaml");
  SensorInfo sensor;
  sensor.range_min = 0.2;
  sensor.range_max = 12.0;
  sensor.angular_accuracy_deg = 1.0;
  const TwoStepFilterParams p = c.resolve(sensor);
  EXPECT_DOUBLE_EQ(p.jump.d_max, 12.0);
  EXPECT_DOUBLE_EQ(p.jump.d_min, 0.2);
  EXPECT_DOUBLE_EQ(p.jump.angular_accuracy_deg, 0.5);
}

// Step 2 measures the range noise over its own window, with step 1's
// minimum of samples a band needs (Beyond the paper 33).
TEST(FilterConfig, StepTwoSamplesTheNoiseWithStepOnesMinimum) {
  const FilterConfig c = parseFilterConfig(
      "jump_filter:\n  noise_estimate_min_samples: 50\n"
      "penetration_filter:\n  evidence_noise_window_scans: 7\n  evidence_noise_sigmas: 3\n",
      "f.yaml");
  const PenetrationFilterParams p = c.resolve(SensorInfo{}).penetration;
  EXPECT_DOUBLE_EQ(p.evidence_noise_sampling.min_samples, 50.0);
  EXPECT_DOUBLE_EQ(p.evidence_noise_sampling.window_scans, 7.0);
  EXPECT_DOUBLE_EQ(p.evidence_noise_sigmas, 3.0);
}

// obs_th and the free-space check's veto count returns, and a surface gives
// more of them the finer the step: each is given for its reference step and
// scaled. The rescue's count is not (measured on the real logs).
TEST(FilterConfig, CountsOfReturnsFollowTheAngularStep) {
  const FilterConfig shipped = loadFilterConfig(SCANFILTER_SOURCE_DIR "/config/filter.yaml");
  const auto at = [&](const FilterConfig& c, double step_deg) {
    SensorInfo sensor;
    sensor.angular_accuracy_deg = step_deg;
    return c.resolve(sensor).penetration;
  };
  const PenetrationFilterParams one_degree = at(shipped, 1.0);
  EXPECT_EQ(one_degree.obstacle_threshold, 2);
  EXPECT_EQ(one_degree.free_space_veto_count, 2);
  EXPECT_EQ(one_degree.rescue_min_count, 5);
  EXPECT_EQ(one_degree.thin_object_min_returns, 1);
  const PenetrationFilterParams quarter = at(shipped, 0.25);
  EXPECT_EQ(quarter.obstacle_threshold, 8);
  EXPECT_EQ(quarter.free_space_veto_count, 8);
  EXPECT_EQ(quarter.rescue_min_count, 5);
  EXPECT_EQ(quarter.thin_object_min_returns, 4);
  EXPECT_EQ(at(shipped, 0.3515625).free_space_veto_count, 6);  // URG-04LX: 1,024 steps a turn
  EXPECT_EQ(at(shipped, 5.0).free_space_veto_count, 1) << "0.4 rounds to 0, and a veto of 0 would need no evidence";
  // The sparse surfaces' support grows with the square root of the beams.
  EXPECT_EQ(one_degree.surface_memory.sparse_surfaces.min_neighbours, 4);
  EXPECT_EQ(one_degree.surface_memory.sparse_surfaces.min_cells, 6);
  EXPECT_EQ(quarter.surface_memory.sparse_surfaces.min_neighbours, 8);
  EXPECT_EQ(quarter.surface_memory.sparse_surfaces.min_cells, 12);
  EXPECT_EQ(at(shipped, 5.0).surface_memory.sparse_surfaces.min_neighbours, 3) << "a line needs three cells";

  const FilterConfig as_given = parseFilterConfig(
      "penetration_filter:\n  obstacle_threshold_reference_deg: 0\n  free_space_veto_reference_deg: 0\n"
      "  surface_memory:\n    sparse_surfaces:\n      support_reference_deg: 0\n",
      "f.yaml");
  const PenetrationFilterParams fixed = at(as_given, 0.25);
  EXPECT_EQ(fixed.obstacle_threshold, 2);
  EXPECT_EQ(fixed.thin_object_min_returns, 1);
  EXPECT_EQ(fixed.free_space_veto_count, 2);
  EXPECT_EQ(fixed.surface_memory.sparse_surfaces.min_cells, 6);
}

// yaml-cpp answers the first of two equal keys: a line appended to override
// a setting would be ignored without a word.
TEST(FilterConfigErrors, AKeyGivenTwiceIsAnErrorNamingBothLines) {
  EXPECT_EQ(errorOf("jump_filter:\n  alpha: 0.6\n  alpha: 50\n"),
            "f.yaml:3: jump_filter.alpha: duplicate key (first on line 2); give each key once");
  EXPECT_EQ(errorOf("penetration_filter:\n  surface_memory:\n    lifetime: 5\npenetration_filter:\n  t_max: 4\n"),
            "f.yaml:4: penetration_filter: duplicate key (first on line 1); give each key once");
  EXPECT_EQ(errorOf("jump_filter:\n  alpha: 0.6\npenetration_filter:\n  alpha: 0.6\n").find("duplicate"),
            std::string::npos)
      << "the same key in two mappings is two keys";
}

// An alias is the node its anchor names: a mapping that holds an alias of
// itself is a cycle, and nine levels of ten aliases a billion nodes. Each
// mapping is checked for keys given twice once, where it is written.
TEST(FilterConfigErrors, AliasesAreNeitherACycleNorABillionNodes) {
  EXPECT_EQ(errorOf("jump_filter: &x {alpha: 0.6, more: *x}\n"),
            "f.yaml:1: jump_filter.more: unknown key (not one of the 23 keys jump_filter takes)")
      << "a cycle";
  std::string laughs = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int level = 1; level < 9; ++level) {
    const std::string a = "*a" + std::to_string(level - 1);
    laughs += "a" + std::to_string(level) + ": &a" + std::to_string(level) + " [" + a;
    for (int i = 1; i < 10; ++i) laughs += ", " + a;
    laughs += "]\n";
  }
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(errorOf(laughs), "f.yaml:1: a0: unknown section; expected jump_filter or penetration_filter");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5)) << "the aliases were followed";
}

// Integers as a person writes them: yaml-cpp alone reads 010 as octal 8.
TEST(FilterConfig, IntegersAreDecimal) {
  const auto frames = [](const std::string& value) {
    return parseFilterConfig("penetration_filter:\n  max_cache_frames: " + value + "\n", "f.yaml")
        .params.penetration.max_cache_frames;
  };
  EXPECT_EQ(frames("010"), 10u);
  EXPECT_EQ(frames("+12"), 12u);
  EXPECT_EQ(errorOf("penetration_filter:\n  max_cache_frames: 0x10\n"),
            "f.yaml:2: penetration_filter.max_cache_frames: expected an integer, got \"0x10\"");
}

TEST(FilterConfigErrors, NameFileLineAndKey) {
  EXPECT_EQ(errorOf("jump_filter:\n  alpha: fast\n"), "f.yaml:2: jump_filter.alpha: expected a number, got \"fast\"");
  EXPECT_EQ(errorOf("jump_filter:\n  alpah: 1\n"), "f.yaml:2: jump_filter.alpah: unknown key (did you mean alpha?)");
  EXPECT_EQ(errorOf("jump_filter:\n  d_max: .inf\n"),
            "f.yaml:2: jump_filter.d_max: expected 0 <= value <= 1e4 (m), or auto, got .inf (not a finite number)");
  EXPECT_EQ(errorOf("jump_filter:\n  alpha: .inf\n"),
            "f.yaml:2: jump_filter.alpha: expected a value > 0, got .inf (not a finite number)");
  EXPECT_EQ(errorOf("jump_filter:\n  alpha: [1, 2]\n"),
            "f.yaml:2: jump_filter.alpha: expected a number, got \"a list or mapping\"");
  EXPECT_EQ(errorOf("penetration_filter:\n  max_cache_frames: 99999999999999999999\n"),
            "f.yaml:2: penetration_filter.max_cache_frames: expected an integer from 0 to 18446744073709551615, got "
            "\"99999999999999999999\"");
  EXPECT_EQ(errorOf("jump_filter:\n  d_min: -1\n"),
            "f.yaml:2: jump_filter.d_min: expected 0 <= value <= 1e4 (m), or auto, got -1");
  EXPECT_EQ(errorOf("jump_filter:\n  theta_k_deg: 90\n"),
            "f.yaml:2: jump_filter.theta_k_deg: expected 0 <= value < 90 (cos θK must stay positive), got 90");
  EXPECT_EQ(errorOf("penetration_filter:\n  min_frames: 0\n"),
            "f.yaml:2: penetration_filter.min_frames: expected an integer >= 1, got 0");
  EXPECT_EQ(errorOf("penetration:\n  x: 1\n"), "f.yaml:1: penetration: unknown section; expected jump_filter or penetration_filter");
  EXPECT_EQ(errorOf("jump_filter: [1, 2\n").substr(0, 26), "f.yaml:2: malformed YAML: ");
  EXPECT_EQ(errorOf("penetration_filter:\n  alignment:\n    max_fit_points: 10\n"),
            "f.yaml:3: penetration_filter.alignment.max_fit_points: must be 0 (every point) or at least min_matches "
            "(20): fewer points could never make a good fit");
  EXPECT_EQ(errorOf("penetration_filter:\n  free_space_min_frames: 41\n"),
            "f.yaml:2: penetration_filter.free_space_min_frames: expected an integer from 1 to max_cache_frames, "
            "got 41");
  EXPECT_EQ(errorOf("penetration_filter:\n  max_cache_frames: 60\n  free_space_min_frames: 41\n"), "no error");
  EXPECT_EQ(errorOf("penetration_filter:\n  surface_memory:\n    surface_margin: 0\n"),
            "f.yaml:3: penetration_filter.surface_memory.surface_margin: expected 0.001 <= value <= 10 (m; returns on "
            "the surface must not count), got 0");
  EXPECT_EQ(errorOf("penetration_filter:\n  surface_memory:\n    behind_margin: 0.2\n"),
            "f.yaml:3: penetration_filter.surface_memory.behind_margin: unknown key (not one of the 25 keys "
            "penetration_filter.surface_memory takes)");
  EXPECT_EQ(errorOf("penetration_filter:\n  surface_memory:\n    head_on_deg: 0\n"),
            "f.yaml:3: penetration_filter.surface_memory.head_on_deg: expected 0 < value <= 45 (degrees off the "
            "normal; head_on_through_beams: 0 turns the rule off), got 0");
  EXPECT_EQ(errorOf("penetration_filter:\n  surface_memory:\n    specular_lifetime: -1\n"),
            "f.yaml:3: penetration_filter.surface_memory.specular_lifetime: expected a value >= 0 (s; at most "
            "lifetime: panes and mirrors live as long as any surface), got -1");
  EXPECT_EQ(errorOf("penetration_filter:\n  surface_memory:\n    sparse_lifetime: -2\n"),
            "f.yaml:3: penetration_filter.surface_memory.sparse_lifetime: expected a value >= 0 (s; lifetime: as long "
            "as a surface a frame saw, as before Beyond the paper 40), got -2");
  EXPECT_EQ(errorOf("penetration_filter:\n  surface_memory:\n    drift_margin_deg_per_m: 50\n"),
            "f.yaml:3: penetration_filter.surface_memory.drift_margin_deg_per_m: expected 0 <= value <= 45 (degrees "
            "per m driven; 0: off), got 50");
  EXPECT_EQ(errorOf("penetration_filter:\n  surface_memory:\n    specular_min_pass_share: 1.5\n"),
            "f.yaml:3: penetration_filter.surface_memory.specular_min_pass_share: expected 0 <= value <= 1 (1: no beam "
            "off the lobe may return on it), got 1.5");
  EXPECT_EQ(errorOf("penetration_filter:\n  surface_memory:\n    mirror_ghosts:\n      line_spread: 0.7\n"),
            "f.yaml:4: penetration_filter.surface_memory.mirror_ghosts.line_spread: expected 0 <= value <= 2 x "
            "line_window (m: the returns lie within line_window either side), got 0.7");
  EXPECT_EQ(errorOf("penetration_filter:\n  surface_memory:\n    mirror_ghosts:\n      image_radius: 0\n"),
            "f.yaml:4: penetration_filter.surface_memory.mirror_ghosts.image_radius: expected 0.001 <= value <= 1 (m), "
            "got 0");
  EXPECT_EQ(errorOf("penetration_filter:\n  free_space_lone_vote_pane_reach: -0.1\n"),
            "f.yaml:2: penetration_filter.free_space_lone_vote_pane_reach: expected 0 <= value <= 10 (m), got -0.1");
  EXPECT_EQ(errorOf("penetration_filter:\n  rescue_min_parallax_deg: 90\n"),
            "f.yaml:2: penetration_filter.rescue_min_parallax_deg: expected 0 <= value <= 89 (degrees; 0: off), "
            "got 90");
  EXPECT_EQ(errorOf("penetration_filter:\n  surface_memory:\n    mirror_ghosts:\n      radius: 0.1\n"),
            "f.yaml:4: penetration_filter.surface_memory.mirror_ghosts.radius: unknown key (expected one of "
            "beyond_proven_mirrors, crossing_band, enabled, image_radius, line_spread, line_tolerance, line_window)");
  EXPECT_EQ(errorOf("penetration_filter:\n  surface_memory:\n    head_on_through_beams: -1\n"),
            "f.yaml:3: penetration_filter.surface_memory.head_on_through_beams: expected an integer >= 0 (0: never "
            "forget so), got -1");
  EXPECT_EQ(errorOf("penetration_filter:\n  surface_memory:\n    max_gap: -0.1\n"),
            "f.yaml:3: penetration_filter.surface_memory.max_gap: expected 0 <= value <= 10 (m; 0: off), got -0.1");
  EXPECT_EQ(errorOf("penetration_filter:\n  surface_memory:\n    max_gap: 0\n"), "no error");
  EXPECT_EQ(errorOf("penetration_filter:\n  surface_memory:\n    sparse_surfaces:\n      max_thickness_noise_sigmas: "
                    "-1\n"),
            "f.yaml:4: penetration_filter.surface_memory.sparse_surfaces.max_thickness_noise_sigmas: expected 0 <= "
            "value <= 100 (σ of the range noise; 0: max_thickness everywhere), got -1");
  EXPECT_EQ(errorOf("penetration_filter:\n  surface_memory:\n    sparse_surfaces:\n      max_deviation_ceiling: 2\n"),
            "f.yaml:4: penetration_filter.surface_memory.sparse_surfaces.max_deviation_ceiling: expected 0 <= value "
            "<= 1 (m), got 2");
  EXPECT_EQ(errorOf("penetration_filter:\n  surface_memory:\n    sparse_surfaces:\n      min_neighbours: 2\n"),
            "f.yaml:4: penetration_filter.surface_memory.sparse_surfaces.min_neighbours: expected an integer >= 3 (a "
            "cell and two more make a line), got 2");
  EXPECT_EQ(errorOf("penetration_filter:\n  surface_memory:\n    sparse_surfaces:\n      max_gap: 0\n"),
            "f.yaml:4: penetration_filter.surface_memory.sparse_surfaces.max_gap: expected 0.001 <= value <= 10 (m), "
            "got 0");
  EXPECT_EQ(errorOf("penetration_filter:\n  surface_memory:\n    sparse_surfaces:\n      min_cels: 6\n"),
            "f.yaml:4: penetration_filter.surface_memory.sparse_surfaces.min_cels: unknown key (did you mean "
            "min_cells?)");
  EXPECT_EQ(errorOf("penetration_filter:\n  free_space_veto_reference_deg: -1\n"),
            "f.yaml:2: penetration_filter.free_space_veto_reference_deg: expected 0 (as given) or the angular step "
            "free_space_veto_count is for, in degrees, got -1");
  EXPECT_EQ(errorOf("penetration_filter:\n  free_space_veto_count: 0\n"),
            "f.yaml:2: penetration_filter.free_space_veto_count: expected an integer >= 1, got 0");
  EXPECT_EQ(errorOf("penetration_filter:\n  thin_object_max_beams: 0\n"),
            "f.yaml:2: penetration_filter.thin_object_max_beams: expected an integer >= 1, got 0");
  EXPECT_EQ(errorOf("penetration_filter:\n  thin_object_radius: 2\n"),
            "f.yaml:2: penetration_filter.thin_object_radius: expected 0 <= value <= 1 (m), got 2");
  EXPECT_EQ(errorOf("penetration_filter:\n  thin_object_min_returns: 0\n"),
            "f.yaml:2: penetration_filter.thin_object_min_returns: expected an integer >= 1, got 0");
  EXPECT_EQ(errorOf("penetration_filter:\n  evidence_noise_sigmas: -1\n"),
            "f.yaml:2: penetration_filter.evidence_noise_sigmas: expected 0 <= value <= 100 (0: off), got -1");
  EXPECT_EQ(errorOf("penetration_filter:\n  evidence_noise_window_scans: 0.5\n"),
            "f.yaml:2: penetration_filter.evidence_noise_window_scans: expected 1-1e6 (scans), got 0.5");
  EXPECT_EQ(errorOf("penetration_filter:\n  evidence_radius_max: 11\n"),
            "f.yaml:2: penetration_filter.evidence_radius_max: expected 0 <= value <= 10 (m), got 11");
  EXPECT_EQ(errorOf("penetration_filter:\n  rescue_radius: 0.5\n"), "no error")
      << "a rescue_radius above evidence_radius_max is the radius everywhere";
  EXPECT_EQ(errorOf("penetration_filter:\n  obstacle_at_centroid: false\n"),
            "f.yaml:2: penetration_filter.require_surface_extent: needs obstacle_at_centroid: true (or set "
            "require_surface_extent: false for cell centres)");
  EXPECT_EQ(errorOf("penetration_filter:\n  obstacle_at_centroid: false\n  require_surface_extent: false\n"), "no error");
  EXPECT_EQ(errorOf("penetration_filter:\n  obstacle_at_centroid: false\n  require_both_sides: false\n"), "no error");
  EXPECT_EQ(errorOf("penetration_filter:\n  thin_object_depth_step: 0\n"),
            "f.yaml:2: penetration_filter.thin_object_depth_step: must be > 0 with thin_object_check (or set "
            "thin_object_check: false)");
  EXPECT_EQ(errorOf("penetration_filter:\n  thin_object_depth_step: 0\n  thin_object_check: false\n"), "no error");
  EXPECT_EQ(errorOf("penetration_filter:\n  thin_object_depth_step: 11\n"),
            "f.yaml:2: penetration_filter.thin_object_depth_step: expected 0 <= value <= 10 (m), got 11");
  EXPECT_EQ(errorOf("penetration_filter:\n  edge_depth_step: 0\n"), "no error")
      << "the thin-object check no longer uses it";
  EXPECT_EQ(errorOf("penetration_filter:\n  cache_min_interval: -0.1\n"),
            "f.yaml:2: penetration_filter.cache_min_interval: expected 0 <= value <= 10 (s; 0: every frame), got -0.1");
  EXPECT_EQ(errorOf("penetration_filter:\n  free_space_margin_per_m: -0.01\n"),
            "f.yaml:2: penetration_filter.free_space_margin_per_m: expected 0 <= value <= 1 (m per m), got -0.01");
  EXPECT_EQ(errorOf("jump_filter:\n  noise_estimate_window_scans: 0\n"),
            "f.yaml:2: jump_filter.noise_estimate_window_scans: expected 1-1e6 (scans), got 0");
}

}  // namespace
}  // namespace scanfilter
