#pragma once
// The physics of one LiDAR: what a beam's footprint, noise and surfaces do
// to its range. docs/simulator.md gives each number's source; the defaults
// are the built-in scenes' own sensor (a sweeping-robot triangulation LiDAR).

namespace scanfilter::sim {

// How the receiver turns light from several depths inside one footprint into
// one range.
enum class RangeMixing {
  // Time of flight: the echo is the sum of the partial echoes, so the range
  // is their mean weighted by the light each part returns.
  kLinear,
  // Triangulation: the spot's image lies at a position proportional to 1/r,
  // and the sensor reads the centroid of the image, so 1/r is the weighted
  // mean of the parts' 1/r.
  kInverseDepth,
};

// A smooth surface's direct return: near normal incidence its mirror
// reflection goes straight back to the sensor (a lobe of width lobe_width_deg
// around the normal); elsewhere only its weak diffuse part can come back.
struct SpecularSurface {
  double lobe_width_deg = 10.0;  // σ of the Gaussian specular lobe, degrees of incidence
  double diffuse_return = 0.1;   // chance of a direct return outside the lobe
};

// Most beams a turn a scene, a sensor file or `simulate --beams` may ask for:
// far beyond any real scanner (a 0.0036° step), low enough that the arrays
// they size fit in memory.
inline constexpr int kMaxSimulatedBeams = 100000;

struct LidarModel {
  RangeMixing mixing = RangeMixing::kInverseDepth;
  int beams = 360;
  double rate_hz = 10.0;
  double range_resolution = 0.001;       // m, ranges are quantised to this
  double noise_sigma_base = 0.003;       // m, σ at zero range
  double noise_sigma_quadratic = 0.001;  // m per m², σ's growth with d² (triangulation)
  // Footprint: its width across the beam at range d is
  // exit_aperture + d * divergence, plus the angle the head turns while the
  // receiver integrates (exposure_sweep of one angular step).
  double beam_divergence_mrad = 1.0;  // full angle
  double exit_aperture = 0.003;       // m, spot width at the window
  double exposure_sweep = 1.0;        // fraction of the angular step swept during one measurement
  int footprint_rays = 16;            // rays sampling the footprint: a fraction resolves to 1/this
  // Spot deformations that the footprint does not model: random
  // displacements at grazing incidence and at wall junctions.
  double grazing_angle_deg = 75.0;  // incidence beyond which the spot deforms
  double grazing_probability = 0.25;
  double grazing_error_max = 0.4;  // m, largest displacement at grazing incidence
  double junction_radius = 0.04;   // m, hits this near a corner can be displaced
  double junction_probability = 0.3;
  double junction_error_max = 0.25;  // m
  // m, a return off every surface by more than max(this, 4σ) is a jump point
  double jump_min_error = 0.05;
  SpecularSurface smooth{10.0, 0.1};
  SpecularSurface glass{5.0, 0.02};
  double glass_refractive_index = 1.5;  // sets the pane's Fresnel reflectance
  double dropout_probability = 0.003;   // a rough surface returning nothing
};

}  // namespace scanfilter::sim
