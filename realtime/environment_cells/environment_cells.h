// An environment map's sphere of directions split into cells of roughly equal power (book
// §4.2.3, Fig. 4.13): centres drawn in proportion to the map's radiance, spread by weighted
// Lloyd relaxation (each texel belongs to its nearest centre, the Voronoi cell on the sphere;
// each centre moves to its cell's weighted centroid), then each cell's total incoming radiance
// Ψ_i = ∫_{Δω_i} L dω and solid angle Δω_i summed over its texels. Every cell becomes one
// directional light with its own shadow map (techniques/environment_shadows/). On the CPU, one
// thread: deterministic. See realtime/techniques/environment_shadows/README.md.
#pragma once

#include "image/image.h"
#include "realtime/environment_cells/spherical_delaunay.h"
#include "scene/environment_map.h"

#include <glm/vec3.hpp>

#include <vector>

namespace gib::rt {

struct EnvironmentCell {
  glm::vec3 direction{0.0f};  // world direction from the scene towards the cell's centre, unit
  // Ψ_i = Σ L·Δω over the cell's texels (the map's intensity included): the irradiance the cell
  // delivers on a plane facing it, W/m² per channel.
  scene::Rgb power{0.0f};
  double solid_angle = 0;  // Δω_i = Σ of its texels' solid angles, sr
  int texels = 0;          // texels in the cell (0: an empty cell, no light)
};

struct EnvironmentCells {
  std::vector<EnvironmentCell> cells;
  // The centres in map directions (scene/environment_map.h), the frame the texels are in.
  std::vector<glm::dvec3> centres;
  // Per texel, row-major as the map's texels: the index of the cell it belongs to.
  std::vector<int> texel_cell;
  // The weighted Lloyd energy Σ w_t·|d_t − c(t)|² after each assignment of texels to centres:
  // relaxation_steps + 1 values, non-increasing.
  std::vector<double> energies;
  double relaxation_ms = 0;  // the relaxation steps alone
  double total_ms = 0;       // initial centres, relaxation and sums
};

// The cells of `map` (not empty). Throws gib::InputError for `cells` below 1 or above the map's
// texel count, a negative `relaxation_steps`, and a black map (no light to divide).
EnvironmentCells buildEnvironmentCells(const scene::EnvironmentMap& map, int cells,
                                       int relaxation_steps);

// The relaxation's weight of a texel of luminance `luminance` (intensity included) and solid
// angle `solid_angle`: luminance² × solid angle. A weighted Lloyd relaxation's cells settle where
// their area is proportional to weight^(−1/2) on a surface (Gersho's asymptotics of centroidal
// Voronoi tessellations, Du, Faber & Gunzburger 1999), so weighting by L² keeps the area ∝ 1/L of
// the initial, radiance-proportional draw: cells of equal power, as the book asks.
double relaxationWeight(double luminance, double solid_angle);

// The half-angle of the spherical cap of solid angle `solid_angle` (sr, in [0, 4π]): the cap the
// integrated reflectivity averages the BRDF over.
double capHalfAngle(double solid_angle);

// The map's texels (intensity included) with the Delaunay triangulation's edges drawn in green
// and the centres in red, at four times the map's mean luminance (Fig. 4.13): the same layout as
// the map (row 0 the zenith).
image::Image drawCellTriangulation(const scene::EnvironmentMap& map, const EnvironmentCells& cells,
                                   const SphericalDelaunay& triangulation);

}  // namespace gib::rt
