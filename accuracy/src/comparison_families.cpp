#include "scanfilter/accuracy/comparison_families.hpp"

#include <algorithm>

#include "scanfilter/accuracy/filter_score.hpp"
#include "scanfilter/baselines/median_image_filter.hpp"
#include "scanfilter/baselines/optics_filter.hpp"
#include "scanfilter/baselines/radius_outlier_filter.hpp"
#include "scanfilter/baselines/scan_shadows_filter.hpp"
#include "scanfilter/baselines/speckle_filter.hpp"

namespace scanfilter::accuracy {

namespace {

int asInt(double v) { return static_cast<int>(v); }

FilterFamily twoStep(const FilterConfig& ours) {
  const auto& j = ours.params.jump;
  const auto& p = ours.params.penetration;
  return {"two-step (ours)",
          "this project: Cao et al. 2025 with the changes in docs/beyond-the-paper.md; defaults config/filter.yaml",
          {{"alpha", {j.alpha, 0.5, 0.8}},
           {"theta_k_deg", {j.theta_k_deg, 60.0, 80.0}},
           {"l_max", {j.l_max, 0.08, 0.12}},
           {"obs_th", {static_cast<double>(p.obstacle_threshold), 3.0}},
           {"min_frames", {static_cast<double>(p.min_frames), 3.0}}},
          [ours](const ParamValues& v, const SensorInfo& sensor) -> std::unique_ptr<ScanFilter> {
            FilterConfig config = ours;
            config.params.jump.alpha = v.at("alpha");
            config.params.jump.theta_k_deg = v.at("theta_k_deg");
            config.params.jump.l_max = v.at("l_max");
            config.params.penetration.obstacle_threshold = asInt(v.at("obs_th"));
            config.params.penetration.min_frames = asInt(v.at("min_frames"));
            return makeTwoStepFilter(config, sensor);
          }};
}

FilterFamily scanShadows() {
  return {"laser_filters shadows",
          "ros-perception/laser_filters ScanShadowsFilter; example config min 10, max 170, window 1, neighbors 20",
          {{"min_angle_deg", {10, 5, 15, 20}},
           {"max_angle_deg", {170, 175, 165}},
           {"window", {1, 2, 3}},
           {"neighbors", {20, 1, 3, 8}},
           {"remove_shadow_start_point", {0, 1}}},
          [](const ParamValues& v, const SensorInfo&) -> std::unique_ptr<ScanFilter> {
            baselines::ScanShadowsParams p;
            p.min_angle_deg = v.at("min_angle_deg");
            p.max_angle_deg = v.at("max_angle_deg");
            p.window = asInt(v.at("window"));
            p.neighbors = asInt(v.at("neighbors"));
            p.remove_shadow_start_point = v.at("remove_shadow_start_point") != 0;
            return std::make_unique<baselines::ScanShadowsFilter>(p);
          }};
}

FilterFamily speckle(baselines::SpeckleMode mode) {
  const bool distance = mode == baselines::SpeckleMode::kDistance;
  return {distance ? "laser_filters speckle (distance)" : "laser_filters speckle (euclidean)",
          "ros-perception/laser_filters LaserScanSpeckleFilter; example config max_range 2, difference 0.1, window 2",
          {{"max_range", {2.0, 4.0, 6.0}},
           {"max_range_difference", {0.1, 0.05, 0.2, 0.3}},
           {"filter_window", {2, 1, 3, 4}}},
          [mode](const ParamValues& v, const SensorInfo&) -> std::unique_ptr<ScanFilter> {
            baselines::SpeckleParams p;
            p.mode = mode;
            p.max_range = v.at("max_range");
            p.max_range_difference = v.at("max_range_difference");
            p.filter_window = asInt(v.at("filter_window"));
            return std::make_unique<baselines::SpeckleFilter>(p);
          }};
}

FilterFamily radiusOutlier() {
  return {"radius outlier",
          "PCL RadiusOutlierRemoval / laser_filters radius outlier; no published scan default: r 0.1 m, k 2",
          {{"radius", {0.10, 0.05, 0.15, 0.20, 0.30}}, {"min_neighbors", {2, 1, 3, 4, 6}}},
          [](const ParamValues& v, const SensorInfo&) -> std::unique_ptr<ScanFilter> {
            return std::make_unique<baselines::RadiusOutlierFilter>(
                baselines::RadiusOutlierParams{v.at("radius"), asInt(v.at("min_neighbors"))});
          }};
}

FilterFamily optics() {
  return {"OPTICS (ellipse)",
          "Zhu et al. (paper ref. 18) on Ankerst et al. 1999; no published 2D defaults: ours in optics_filter.hpp",
          {{"eps", {0.20, 0.30}},
           {"axis_ratio", {0.5, 0.3, 1.0}},
           {"min_pts", {4, 3, 6}},
           {"eps_cluster", {0.15, 0.05, 0.10}},
           {"min_cluster_size", {4, 2, 8}}},
          [](const ParamValues& v, const SensorInfo&) -> std::unique_ptr<ScanFilter> {
            baselines::OpticsParams p;
            p.eps = v.at("eps");
            p.axis_ratio = v.at("axis_ratio");
            p.min_pts = asInt(v.at("min_pts"));
            p.eps_cluster = std::min(v.at("eps_cluster"), p.eps);
            p.min_cluster_size = asInt(v.at("min_cluster_size"));
            return std::make_unique<baselines::OpticsFilter>(p);
          }};
}

FilterFamily medianImage() {
  return {"median image (Wang)",
          "Wang (paper ref. 8); no published defaults: ours in median_image_filter.hpp",
          {{"cell_size", {0.05, 0.10}},
           {"frames", {10, 5, 20}},
           {"window", {3, 1, 5}},
           {"ignore_empty", {1, 0}},
           {"threshold", {3, 2, 4, 6}}},
          [](const ParamValues& v, const SensorInfo&) -> std::unique_ptr<ScanFilter> {
            baselines::MedianImageParams p;
            p.cell_size = v.at("cell_size");
            p.frames = asInt(v.at("frames"));
            p.window = asInt(v.at("window"));
            p.ignore_empty = v.at("ignore_empty") != 0;
            p.threshold = asInt(v.at("threshold"));
            return std::make_unique<baselines::MedianImageFilter>(p);
          }};
}

}  // namespace

std::vector<FilterFamily> comparisonFamilies(const FilterConfig& ours) {
  return {twoStep(ours),
          scanShadows(),
          speckle(baselines::SpeckleMode::kDistance),
          speckle(baselines::SpeckleMode::kEuclidean),
          radiusOutlier(),
          optics(),
          medianImage()};
}

}  // namespace scanfilter::accuracy
