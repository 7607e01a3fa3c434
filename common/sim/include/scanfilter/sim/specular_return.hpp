#pragma once
// What a smooth surface or a glass pane does with a beam: how likely it
// returns the beam directly, and how much of it a pane reflects (the rest it
// lets through).

#include "scanfilter/sim/lidar_model.hpp"

namespace scanfilter::sim {

// Chance that the surface itself is seen at this incidence (rad from its
// normal): inside the specular lobe the mirror reflection comes straight
// back; outside it only the diffuse part can.
double directReturnProbability(const SpecularSurface& surface, double incidence);

// Fraction of unpolarised light a clear pane of this refractive index
// reflects at this incidence (rad): Fresnel's equations at each of its two
// faces, their repeated reflections added without absorption (2R / (1 + R)).
double paneReflectance(double incidence, double refractive_index);

}  // namespace scanfilter::sim
