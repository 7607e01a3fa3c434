#include "scanfilter/filter_config.hpp"

#include <algorithm>
#include <cmath>

#include "scanfilter/input_error.hpp"
#include "scanfilter/plausible_bounds.hpp"
#include "scanfilter/yaml_section.hpp"

namespace scanfilter {

namespace {

void readJump(YamlSection& s, FilterConfig& config) {
  JumpFilterParams& p = config.params.jump;
  s.read("enabled", config.params.jump_enabled);
  s.readAuto("angular_accuracy_deg", config.angular_accuracy_deg);
  s.read("alpha", p.alpha);
  s.read("theta_k_deg", p.theta_k_deg);
  s.read("l_min", p.l_min);
  s.read("l_max", p.l_max);
  s.readAuto("d_min", config.d_min);
  s.readAuto("d_max", config.d_max);
  std::string span = p.span_range == SpanRange::kSeed ? "seed" : "cluster_mean";
  s.readChoice("span_range", span, {"cluster_mean", "seed"});
  p.span_range = span == "seed" ? SpanRange::kSeed : SpanRange::kClusterMean;
  s.read("off_surface_check", p.off_surface_check);
  s.read("off_surface_min", p.off_surface_min);
  s.read("off_surface_sigmas", p.off_surface_sigmas);
  s.read("noise_sigma_base", p.noise_sigma_base);
  s.read("noise_sigma_quadratic", p.noise_sigma_quadratic);
  s.read("noise_estimate", p.noise_estimate);
  s.read("noise_estimate_window_scans", p.noise_sampling.window_scans);
  s.read("noise_estimate_min_samples", p.noise_sampling.min_samples);
  s.read("radius_noise_sigmas", p.radius_noise_sigmas);
  s.read("straight_runs", p.straight_runs);
  s.read("straight_run_max_incidence_deg", p.straight_run_max_incidence_deg);
  s.read("straight_run_min_points", p.straight_run_min_points);
  s.read("keep_foreground_clusters", p.keep_foreground_clusters);
  s.read("keep_unresolved_returns", p.keep_unresolved_returns);
  if (config.angular_accuracy_deg) s.requireRange("angular_accuracy_deg", *config.angular_accuracy_deg, 1e-6, 90.0, "0 < value <= 90");
  s.requireRange("alpha", p.alpha, 1e-9, 1e9, "a value > 0");
  s.requireRange("theta_k_deg", p.theta_k_deg, 0.0, 89.9, "0 <= value < 90 (cos θK must stay positive)");
  s.requireRange("l_min", p.l_min, 0.0, 1e9, "a value >= 0");
  s.requireRange("l_max", p.l_max, 0.0, 1e9, "a value >= 0");
  s.requireRange("off_surface_min", p.off_surface_min, 0.0, 1e9, "a value >= 0 (m)");
  s.requireRange("off_surface_sigmas", p.off_surface_sigmas, 0.0, 1e9, "a value >= 0");
  s.requireRange("noise_sigma_base", p.noise_sigma_base, 0.0, 1e9, "a value >= 0 (m)");
  s.requireRange("noise_sigma_quadratic", p.noise_sigma_quadratic, 0.0, 1e9, "a value >= 0 (m per m²)");
  s.requireRange("noise_estimate_window_scans", p.noise_sampling.window_scans, 1.0, 1e6, "1-1e6 (scans)");
  s.requireRange("noise_estimate_min_samples", p.noise_sampling.min_samples, 1.0, 1e9, "a value >= 1 (residuals)");
  s.requireRange("radius_noise_sigmas", p.radius_noise_sigmas, 0.0, 100.0, "0-100");
  s.requireRange("straight_run_max_incidence_deg", p.straight_run_max_incidence_deg, 0.0, 89.9, "0-89.9 (degrees)");
  s.requireRange("straight_run_min_points", p.straight_run_min_points, 3, 1e6, "an integer >= 3");
  // Ranges, as a sensor's are: an infinite d_max (a fuzzed config) sized the
  // noise estimate's range bands from infinity.
  if (config.d_min) s.requireRange("d_min", *config.d_min, 0.0, kMaxPlausibleRange, "0 <= value <= 1e4 (m), or auto");
  if (config.d_max) s.requireRange("d_max", *config.d_max, 0.0, kMaxPlausibleRange, "0 <= value <= 1e4 (m), or auto");
  if (config.d_min && config.d_max && !(*config.d_max > *config.d_min)) s.fail("d_max", "expected d_max > d_min");
  s.rejectUnknownKeys();
}

void readSparseSurfaces(const YamlSection& parent, SparseSurfaceParams& p, double& support_reference_deg) {
  YamlSection s(parent.node(), "sparse_surfaces", parent.file(), parent.path());
  s.read("enabled", p.enabled);
  s.read("min_beam_surface_angle_deg", p.min_beam_surface_angle_deg);
  s.read("neighbour_radius", p.neighbour_radius);
  s.read("min_neighbours", p.min_neighbours);
  s.read("max_thickness", p.max_thickness);
  s.read("max_thickness_noise_sigmas", p.max_thickness_noise_sigmas);
  s.read("max_thickness_ceiling", p.max_thickness_ceiling);
  s.read("max_angle_deg", p.max_angle_deg);
  s.read("max_gap", p.max_gap);
  s.read("max_deviation", p.max_deviation);
  s.read("max_deviation_noise_sigmas", p.max_deviation_noise_sigmas);
  s.read("max_deviation_ceiling", p.max_deviation_ceiling);
  s.read("min_cells", p.min_cells);
  s.read("min_length", p.min_length);
  s.read("support_reference_deg", support_reference_deg);
  s.requireRange("min_beam_surface_angle_deg", p.min_beam_surface_angle_deg, 0.0, 90.0,
                 "0 <= value <= 90 (degrees; 90: head-on only)");
  s.requireRange("neighbour_radius", p.neighbour_radius, 1e-3, 10.0, "0.001 <= value <= 10 (m)");
  s.requireRange("min_neighbours", p.min_neighbours, 3, 1e6, "an integer >= 3 (a cell and two more make a line)");
  s.requireRange("max_thickness", p.max_thickness, 0.0, 1.0, "0 <= value <= 1 (m)");
  s.requireRange("max_thickness_noise_sigmas", p.max_thickness_noise_sigmas, 0.0, 100.0,
                 "0 <= value <= 100 (σ of the range noise; 0: max_thickness everywhere)");
  s.requireRange("max_thickness_ceiling", p.max_thickness_ceiling, 0.0, 1.0, "0 <= value <= 1 (m)");
  s.requireRange("max_angle_deg", p.max_angle_deg, 0.0, 90.0, "0 <= value <= 90 (degrees)");
  s.requireRange("max_gap", p.max_gap, 1e-3, 10.0, "0.001 <= value <= 10 (m)");
  s.requireRange("max_deviation", p.max_deviation, 0.0, 1.0, "0 <= value <= 1 (m)");
  s.requireRange("max_deviation_noise_sigmas", p.max_deviation_noise_sigmas, 0.0, 100.0,
                 "0 <= value <= 100 (σ of the range noise; 0: max_deviation everywhere)");
  s.requireRange("max_deviation_ceiling", p.max_deviation_ceiling, 0.0, 1.0, "0 <= value <= 1 (m)");
  s.requireRange("min_cells", p.min_cells, 2, 1e6, "an integer >= 2 (two cells make a line)");
  s.requireRange("min_length", p.min_length, 1e-3, 100.0, "0.001 <= value <= 100 (m)");
  s.requireRange("support_reference_deg", support_reference_deg, 0.0, 90.0,
                 "0 (as given) or the angular step min_neighbours and min_cells are for, in degrees");
  s.rejectUnknownKeys();
}

void readMirrorGhosts(const YamlSection& parent, MirrorGhostParams& g) {
  YamlSection s(parent.node(), "mirror_ghosts", parent.file(), parent.path());
  s.read("enabled", g.enabled);
  s.read("image_radius", g.image_radius);
  s.read("line_window", g.line_window);
  s.read("line_tolerance", g.line_tolerance);
  s.read("line_spread", g.line_spread);
  s.read("crossing_band", g.crossing_band);
  s.read("beyond_proven_mirrors", g.beyond_proven_mirrors);
  s.requireRange("image_radius", g.image_radius, 1e-3, 1.0, "0.001 <= value <= 1 (m)");
  s.requireRange("line_window", g.line_window, 1e-3, 10.0, "0.001 <= value <= 10 (m)");
  s.requireRange("line_tolerance", g.line_tolerance, 0.0, 1.0, "0 <= value <= 1 (m)");
  s.requireRange("line_spread", g.line_spread, 0.0, 2.0 * g.line_window,
                 "0 <= value <= 2 x line_window (m: the returns lie within line_window either side)");
  s.requireRange("crossing_band", g.crossing_band, g.line_tolerance, 1.0,
                 "line_tolerance <= value <= 1 (m: beyond the line's own returns)");
  s.rejectUnknownKeys();
}

void readSurfaceMemory(const YamlSection& parent, SurfaceMemoryParams& m, double& sparse_support_reference_deg) {
  YamlSection s(parent.node(), "surface_memory", parent.file(), parent.path());
  s.read("lifetime", m.lifetime);
  s.read("min_interval", m.min_interval);
  s.read("min_beam_surface_angle_deg", m.min_beam_surface_angle_deg);
  s.read("surface_margin", m.surface_margin);
  s.read("surface_margin_per_m", m.surface_margin_per_m);
  s.read("end_margin", m.end_margin);
  s.read("merge_angle_deg", m.merge_angle_deg);
  s.read("merge_offset", m.merge_offset);
  s.read("max_segments", m.max_segments);
  s.read("head_on_deg", m.head_on_deg);
  s.read("head_on_through_beams", m.head_on_through_beams);
  s.read("specular_lifetime", m.specular_lifetime);
  s.read("sparse_lifetime", m.sparse_lifetime);
  s.read("specular_confirm_distance", m.specular_confirm_distance);
  s.read("specular_min_pass_share", m.specular_min_pass_share);
  s.read("drift_margin_per_m", m.drift_margin_per_m);
  s.read("drift_margin_deg_per_m", m.drift_margin_deg_per_m);
  s.read("max_spacing", m.segments.max_spacing);
  s.read("max_deviation", m.segments.max_deviation);
  s.read("min_returns", m.segments.min_returns);
  s.read("min_length", m.segments.min_length);
  s.read("end_step", m.segments.end_step);
  s.read("max_gap", m.segments.max_gap);
  s.take("sparse_surfaces");
  readSparseSurfaces(s, m.sparse_surfaces, sparse_support_reference_deg);
  s.take("mirror_ghosts");
  readMirrorGhosts(s, m.mirror_ghosts);
  s.requireRange("lifetime", m.lifetime, 0.0, 1e6, "a value >= 0 (s; 0: off)");
  s.requireRange("min_interval", m.min_interval, 0.0, 60.0, "0 <= value <= 60 (s)");
  s.requireRange("min_beam_surface_angle_deg", m.min_beam_surface_angle_deg, 0.0, 90.0,
                 "0 <= value <= 90 (degrees; 90: head-on only)");
  s.requireRange("surface_margin", m.surface_margin, 1e-3, 10.0, "0.001 <= value <= 10 (m; returns on the surface must not count)");
  s.requireRange("surface_margin_per_m", m.surface_margin_per_m, 0.0, 1.0, "0 <= value <= 1 (m per m)");
  s.requireRange("end_margin", m.end_margin, 0.0, 10.0, "0 <= value <= 10 (m)");
  s.requireRange("merge_angle_deg", m.merge_angle_deg, 0.0, 45.0, "0 <= value <= 45 (degrees)");
  s.requireRange("merge_offset", m.merge_offset, 0.0, 10.0, "0 <= value <= 10 (m)");
  s.requireRange("max_segments", static_cast<double>(m.max_segments), 1, 1e7, "an integer >= 1");
  s.requireRange("head_on_deg", m.head_on_deg, 1e-3, 45.0,
                 "0 < value <= 45 (degrees off the normal; head_on_through_beams: 0 turns the rule off)");
  s.requireRange("head_on_through_beams", m.head_on_through_beams, 0, 1e6, "an integer >= 0 (0: never forget so)");
  s.requireRange("specular_lifetime", m.specular_lifetime, 0.0, 1e6,
                 "a value >= 0 (s; at most lifetime: panes and mirrors live as long as any surface)");
  s.requireRange("sparse_lifetime", m.sparse_lifetime, 0.0, 1e6,
                 "a value >= 0 (s; lifetime: as long as a surface a frame saw, as before Beyond the paper 40)");
  s.requireRange("specular_confirm_distance", m.specular_confirm_distance, 1e-3, 1.0, "0.001 <= value <= 1 (m)");
  s.requireRange("specular_min_pass_share", m.specular_min_pass_share, 0.0, 1.0,
                 "0 <= value <= 1 (1: no beam off the lobe may return on it)");
  s.requireRange("drift_margin_per_m", m.drift_margin_per_m, 0.0, 1.0, "0 <= value <= 1 (m per m driven; 0: off)");
  s.requireRange("drift_margin_deg_per_m", m.drift_margin_deg_per_m, 0.0, 45.0,
                 "0 <= value <= 45 (degrees per m driven; 0: off)");
  s.requireRange("max_spacing", m.segments.max_spacing, 1e-3, 10.0, "0.001 <= value <= 10 (m)");
  s.requireRange("max_deviation", m.segments.max_deviation, 0.0, 1.0, "0 <= value <= 1 (m)");
  s.requireRange("min_returns", m.segments.min_returns, 2, 1e6, "an integer >= 2 (two returns make a line)");
  s.requireRange("min_length", m.segments.min_length, 1e-3, 100.0, "0.001 <= value <= 100 (m)");
  s.requireRange("end_step", m.segments.end_step, 0.0, 10.0, "0 <= value <= 10 (m)");
  s.requireRange("max_gap", m.segments.max_gap, 0.0, 10.0, "0 <= value <= 10 (m; 0: off)");
  s.rejectUnknownKeys();
}

void readAlignment(const YamlSection& parent, FrameAlignmentParams& a) {
  YamlSection s(parent.node(), "alignment", parent.file(), parent.path());
  s.read("enabled", a.enabled);
  s.read("max_iterations", a.max_iterations);
  s.read("max_match_distance", a.max_match_distance);
  s.read("max_neighbour_span", a.max_neighbour_span);
  s.read("max_off_line", a.max_off_line);
  s.read("min_matched_share", a.min_matched_share);
  s.read("min_matches", a.min_matches);
  s.read("max_rms", a.max_rms);
  s.read("min_rms_gain", a.min_rms_gain);
  s.read("max_fit_points", a.max_fit_points);
  s.requireRange("max_iterations", a.max_iterations, 1, 100, "an integer 1-100");
  s.requireRange("max_match_distance", a.max_match_distance, 1e-3, 2.0, "0.001-2 (m)");
  s.requireRange("max_neighbour_span", a.max_neighbour_span, 1e-3, 10.0, "0.001-10 (m)");
  s.requireRange("max_off_line", a.max_off_line, 0.0, 1.0, "0-1 (m)");
  s.requireRange("min_matched_share", a.min_matched_share, 0.0, 1.0, "0-1");
  s.requireRange("min_matches", a.min_matches, 3, 1e6, "an integer >= 3 (three unknowns)");
  s.requireRange("max_rms", a.max_rms, 0.0, 1.0, "0-1 (m)");
  s.requireRange("min_rms_gain", a.min_rms_gain, 0.0, 1.0, "0-1 (m)");
  s.requireRange("max_fit_points", a.max_fit_points, 0, 1e6, "an integer >= 0 (0: every point)");
  if (a.max_fit_points != 0 && a.max_fit_points < a.min_matches)
    s.fail("max_fit_points", "must be 0 (every point) or at least min_matches (" + std::to_string(a.min_matches) +
                                 "): fewer points could never make a good fit");
  s.rejectUnknownKeys();
}

void readPenetration(YamlSection& s, FilterConfig& config) {
  PenetrationFilterParams& p = config.params.penetration;
  s.read("enabled", config.params.penetration_enabled);
  s.read("cell_size", p.cell_size);
  s.read("frame_lifetime", p.frame_lifetime);
  s.read("min_frames", p.min_frames);
  s.read("obstacle_threshold", p.obstacle_threshold);
  s.read("obstacle_threshold_reference_deg", config.obstacle_threshold_reference_deg);
  s.requireRange("obstacle_threshold_reference_deg", config.obstacle_threshold_reference_deg, 0.0, 90.0,
                 "0 (as given) or the angular step obs_th is for, in degrees");
  s.read("free_space_veto_reference_deg", config.free_space_veto_reference_deg);
  s.requireRange("free_space_veto_reference_deg", config.free_space_veto_reference_deg, 0.0, 90.0,
                 "0 (as given) or the angular step free_space_veto_count is for, in degrees");
  s.read("corridor_half_width", p.corridor_half_width);
  s.read("obstacle_at_centroid", p.obstacle_at_centroid);
  s.read("require_both_sides", p.require_both_sides);
  s.read("straddle_half_width", p.straddle_half_width);
  s.read("surface_gap", p.surface_gap);
  s.read("require_surface_extent", p.require_surface_extent);
  s.read("own_surface_margin", p.own_surface_margin);
  s.read("own_surface_margin_per_m", p.own_surface_margin_per_m);
  s.read("grazing_margin", p.grazing_margin);
  s.read("grazing_margin_max", p.grazing_margin_max);
  s.read("behind_margin", p.behind_margin);
  s.read("pose_jump_reset", p.pose_jump_reset);
  s.read("max_cache_frames", p.max_cache_frames);
  s.read("cache_min_interval", p.cache_min_interval);
  s.read("cache_misdetected_points", p.cache_misdetected_points);
  s.read("edge_vote_margin_deg", p.edge_vote_margin_deg);
  s.read("edge_depth_step", p.edge_depth_step);
  s.read("edge_smear_radius", p.edge_smear_radius);
  s.read("grazing_vote_max_deg", p.grazing_vote_max_deg);
  s.read("rescue_persistent_points", p.rescue_persistent_points);
  s.read("rescue_min_count", p.rescue_min_count);
  s.read("rescue_radius", p.rescue_radius);
  s.read("evidence_noise_sigmas", p.evidence_noise_sigmas);
  s.read("evidence_noise_window_scans", p.evidence_noise_sampling.window_scans);
  s.read("evidence_radius_max", p.evidence_radius_max);
  s.read("rescue_min_baseline", p.rescue_min_baseline);
  s.read("rescue_min_parallax_deg", p.rescue_min_parallax_deg);
  s.read("free_space_check", p.free_space_check);
  s.read("free_space_margin", p.free_space_margin);
  s.read("free_space_margin_per_m", p.free_space_margin_per_m);
  s.read("free_space_dip", p.free_space_dip);
  s.read("free_space_min_frames", p.free_space_min_frames);
  s.read("free_space_veto_count", p.free_space_veto_count);
  s.read("free_space_lone_returns_vote", p.free_space_lone_returns_vote);
  s.read("free_space_lone_votes_beyond_panes", p.free_space_lone_votes_beyond_panes);
  s.read("free_space_lone_vote_pane_reach", p.free_space_lone_vote_pane_reach);
  s.read("thin_object_check", p.thin_object_check);
  s.read("thin_object_max_beams", p.thin_object_max_beams);
  s.read("thin_object_radius", p.thin_object_radius);
  s.read("thin_object_depth_step", p.thin_object_depth_step);
  s.read("thin_object_min_returns", p.thin_object_min_returns);
  s.read("thin_object_beside_no_return", p.thin_object_beside_no_return);
  s.read("thin_object_evidence_kept", p.thin_object_evidence_kept);
  s.read("thin_object_kept_from_afar", p.thin_object_kept_from_afar);
  s.take("alignment");
  readAlignment(s, p.alignment);
  s.take("surface_memory");
  readSurfaceMemory(s, p.surface_memory, config.sparse_support_reference_deg);
  s.requireRange("cell_size", p.cell_size, 1e-3, 10.0, "0.001 <= value <= 10 (m)");
  s.requireRange("frame_lifetime", p.frame_lifetime, 0.0, 1e9, "a value >= 0 (s)");
  s.requireRange("min_frames", p.min_frames, 1, 1e9, "an integer >= 1");
  s.requireRange("obstacle_threshold", p.obstacle_threshold, 0, 1e9, "an integer >= 0");
  s.requireRange("corridor_half_width", p.corridor_half_width, 0.0, 1e9, "a value >= 0 (m)");
  s.requireRange("own_surface_margin", p.own_surface_margin, 0.0, 1e9, "a value >= 0 (m)");
  s.requireRange("own_surface_margin_per_m", p.own_surface_margin_per_m, 0.0, 1e9, "a value >= 0");
  s.requireRange("grazing_margin_max", p.grazing_margin_max, 0.0, 1e9, "a value >= 0 (m)");
  s.requireRange("straddle_half_width", p.straddle_half_width, 0.0, 1e9, "a value >= 0 (m)");
  s.requireRange("surface_gap", p.surface_gap, 0.0, 1e9, "a value >= 0 (m)");
  s.requireRange("behind_margin", p.behind_margin, 0.0, 1e9, "a value >= 0 (m)");
  s.requireRange("pose_jump_reset", p.pose_jump_reset, 0.0, 1e9, "a value > 0 (m)");
  s.requireRange("max_cache_frames", static_cast<double>(p.max_cache_frames), 1, 1e7, "an integer >= 1");
  s.requireRange("cache_min_interval", p.cache_min_interval, 0.0, 10.0, "0 <= value <= 10 (s; 0: every frame)");
  s.requireRange("rescue_min_count", p.rescue_min_count, 1, 1e9, "an integer >= 1");
  s.requireRange("rescue_radius", p.rescue_radius, 0.0, 1.0, "0 <= value <= 1 (m)");
  s.requireRange("evidence_noise_sigmas", p.evidence_noise_sigmas, 0.0, 100.0, "0 <= value <= 100 (0: off)");
  s.requireRange("evidence_noise_window_scans", p.evidence_noise_sampling.window_scans, 1.0, 1e6, "1-1e6 (scans)");
  // Below rescue_radius it changes nothing (the radius is never less), so a
  // larger rescue_radius alone stays a valid config.
  s.requireRange("evidence_radius_max", p.evidence_radius_max, 0.0, 10.0, "0 <= value <= 10 (m)");
  s.requireRange("rescue_min_baseline", p.rescue_min_baseline, 0.0, 100.0, "0 <= value <= 100 (m; 0: off)");
  s.requireRange("rescue_min_parallax_deg", p.rescue_min_parallax_deg, 0.0, 89.0,
                 "0 <= value <= 89 (degrees; 0: off)");
  s.requireRange("edge_vote_margin_deg", p.edge_vote_margin_deg, 0.0, 45.0, "0 <= value <= 45 (degrees; 0: off)");
  s.requireRange("edge_depth_step", p.edge_depth_step, 0.0, 10.0, "0 <= value <= 10 (m)");
  s.requireRange("edge_smear_radius", p.edge_smear_radius, 0.0, 1.0, "0 <= value <= 1 (m; 0: off)");
  s.requireRange("grazing_vote_max_deg", p.grazing_vote_max_deg, 0.0, 45.0, "0 <= value <= 45 (degrees; 0: off)");
  s.requireRange("free_space_margin", p.free_space_margin, 0.0, 10.0, "0 <= value <= 10 (m)");
  s.requireRange("free_space_margin_per_m", p.free_space_margin_per_m, 0.0, 1.0, "0 <= value <= 1 (m per m)");
  s.requireRange("free_space_dip", p.free_space_dip, 0.0, 10.0, "0 <= value <= 10 (m)");
  s.requireRange("free_space_lone_vote_pane_reach", p.free_space_lone_vote_pane_reach, 0.0, 10.0,
                 "0 <= value <= 10 (m)");
  // More than the cache holds would switch the check off without a word.
  s.requireRange("free_space_min_frames", p.free_space_min_frames, 1, static_cast<double>(p.max_cache_frames),
                 "an integer from 1 to max_cache_frames");
  s.requireRange("free_space_veto_count", p.free_space_veto_count, 1, 1e9, "an integer >= 1");
  s.requireRange("thin_object_max_beams", p.thin_object_max_beams, 1, 1e9, "an integer >= 1");
  s.requireRange("thin_object_min_returns", p.thin_object_min_returns, 1, 1e9, "an integer >= 1");
  s.requireRange("thin_object_radius", p.thin_object_radius, 0.0, 1.0, "0 <= value <= 1 (m)");
  // With no depth step every local minimum would stand in front, and a return's own cell in front of it.
  s.requireRange("thin_object_depth_step", p.thin_object_depth_step, 0.0, 10.0, "0 <= value <= 10 (m)");
  if (p.thin_object_check && !(p.thin_object_depth_step > 0.0))
    s.fail("thin_object_depth_step", "must be > 0 with thin_object_check (or set thin_object_check: false)");
  // Cell centres of a slanted wall one cell thick form a staircase: the next
  // centre past two neighbours across a beam is never on their line, so every
  // crossing of such a wall would be refused.
  if (p.require_both_sides && p.require_surface_extent && !p.obstacle_at_centroid)
    s.fail("require_surface_extent",
           "needs obstacle_at_centroid: true (or set require_surface_extent: false for cell centres)");
  s.rejectUnknownKeys();
}

// How many more beams the sensor sends than one at the reference step.
double beamsPerReferenceStep(double reference_deg, const JumpFilterParams& jump) {
  return reference_deg / jump.angular_accuracy_deg;
}

// count x factor, rounded, at least `least`; clamped before the cast, so
// that a huge configured count at a fine step cannot wrap around.
int scaledCount(int count, double factor, int least) {
  const double scaled = std::round(static_cast<double>(count) * factor);
  return static_cast<int>(std::clamp(scaled, static_cast<double>(least), 1e9));
}

}  // namespace

FilterConfig parseFilterConfig(const std::string& yaml_text, const std::string& name) {
  return filterConfigFromYaml(parseYaml(yaml_text, name), name);
}

FilterConfig filterConfigFromYaml(const YAML::Node& root, const std::string& name) {
  FilterConfig config;
  if (!root || root.IsNull()) return config;
  if (!root.IsMap()) throw InputError(name, 1, "", "expected a mapping at the top level");
  for (const auto& entry : root) {
    const auto key = keyText(entry.first, name);
    if (key != "jump_filter" && key != "penetration_filter")
      throw InputError(name, static_cast<std::size_t>(entry.first.Mark().line) + 1, key,
                       "unknown section; expected jump_filter or penetration_filter");
  }
  YamlSection jump(root, "jump_filter", name);
  readJump(jump, config);
  YamlSection penetration(root, "penetration_filter", name);
  readPenetration(penetration, config);
  return config;
}

FilterConfig loadFilterConfig(const std::string& path) { return filterConfigFromYaml(loadYamlFile(path), path); }

TwoStepFilterParams FilterConfig::resolve(const SensorInfo& sensor) const {
  TwoStepFilterParams out = params;
  out.jump.angular_accuracy_deg = angular_accuracy_deg.value_or(sensor.angular_accuracy_deg);
  out.jump.d_min = d_min.value_or(sensor.range_min);
  out.jump.d_max = d_max.value_or(sensor.range_max);
  PenetrationFilterParams& p = out.penetration;
  // Step 2 measures the range noise as step 1 does, over its own window
  // (evidence_radius.hpp).
  p.evidence_noise_sampling.min_samples = out.jump.noise_sampling.min_samples;
  if (obstacle_threshold_reference_deg > 0.0) {
    const double beams = beamsPerReferenceStep(obstacle_threshold_reference_deg, out.jump);
    p.obstacle_threshold = scaledCount(p.obstacle_threshold, beams, 0);
    p.thin_object_min_returns = scaledCount(p.thin_object_min_returns, beams, 1);
  }
  if (free_space_veto_reference_deg > 0.0) {
    // rescue_min_count is not scaled: measured, scaling it too lost more
    // re-observed returns on the real logs (docs/beyond-the-paper.md, 26).
    const double beams = beamsPerReferenceStep(free_space_veto_reference_deg, out.jump);
    p.free_space_veto_count = scaledCount(p.free_space_veto_count, beams, 1);
  }
  if (sparse_support_reference_deg > 0.0) {
    SparseSurfaceParams& sparse = p.surface_memory.sparse_surfaces;
    const double scale = std::sqrt(beamsPerReferenceStep(sparse_support_reference_deg, out.jump));
    sparse.min_neighbours = scaledCount(sparse.min_neighbours, scale, 3);  // a cell and two more make a line
    sparse.min_cells = scaledCount(sparse.min_cells, scale, 2);
  }
  return out;
}

}  // namespace scanfilter
