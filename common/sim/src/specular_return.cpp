#include "scanfilter/sim/specular_return.hpp"

#include <cmath>
#include <numbers>

namespace scanfilter::sim {

double directReturnProbability(const SpecularSurface& surface, double incidence) {
  const double width = surface.lobe_width_deg * std::numbers::pi / 180.0;
  const double lobe = width > 0.0 ? std::exp(-0.5 * (incidence / width) * (incidence / width)) : 0.0;
  return lobe + (1.0 - lobe) * surface.diffuse_return;
}

double paneReflectance(double incidence, double n) {
  const double cos_i = std::cos(incidence);
  const double sin_t = std::sin(incidence) / n;  // Snell: air to glass
  const double cos_t = std::sqrt(1.0 - sin_t * sin_t);
  const double rs = (cos_i - n * cos_t) / (cos_i + n * cos_t);
  const double rp = (cos_t - n * cos_i) / (cos_t + n * cos_i);
  const double face = 0.5 * (rs * rs + rp * rp);
  return 2.0 * face / (1.0 + face);
}

}  // namespace scanfilter::sim
