// The texture atlas shared by the atlas techniques (stochastic radiosity, book §7.1 and Barsi &
// Jakab; later light path maps, obscurances, PRT): every surface of the scene gets texels in
// proportion to its area, so that a texel stands for an elementary surface A^(i) of eq. (7.2).
//
// CPU side only, testable without GL. Triangles are grouped into planar charts (edge-connected,
// coplanar triangles of one mesh and one material: a wall's two triangles become one rectangle),
// each chart is laid flat in its own plane, scaled by one factor for the whole scene (texels per
// scene unit, so texel area is uniform, as the paper recommends) and shelf-packed into the square
// atlas with a gutter around it. Then every texel is baked: the exact area of the surface it covers
// (texel square clipped against the chart's triangles), the centroid of that part as its sample
// point (inside the surface even at a chart's edge, so centre-point visibility does not test a
// point hidden under the neighbouring wall), its normal and its triangle. Gutter texels (area 0)
// copy the sample point of the nearest covered texel of their chart: a bilinear lookup at a chart's
// edge then blends copies of the chart's own values, never black and never a neighbour's light.
#pragma once

#include "scene/scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace gib::rt::atlas {

// A triangle of the scene in world space, in the order of scene::Scene's meshes (the order in
// which GpuScene uploads them).
struct AtlasTriangle {
  std::array<glm::vec3, 3> p;
  glm::vec3 normal{0.0f};  // unit geometric normal (b − a) × (c − a); zero if degenerate
  float area = 0;
  std::uint32_t material = 0;
  std::uint32_t mesh = 0;
  glm::uvec3 indices{0};  // vertex indices in the mesh, for edge adjacency
};

std::vector<AtlasTriangle> atlasTriangles(const scene::Scene& scene);

// A chart's place in the atlas, in texels (x to the right, y upwards: GL's texel rows).
struct ChartRect {
  int x = 0, y = 0, width = 0, height = 0;  // including the gutter
};

struct AtlasLayout {
  int resolution = 0;         // texels per side
  float texels_per_unit = 0;  // scale of every chart: texel side = 1 / texels_per_unit
  std::vector<ChartRect> charts;
  std::vector<int> chart_of_triangle;  // −1 for degenerate triangles (no texels)
  // Each triangle's vertices in texel units (0..resolution); divide by resolution for UVs.
  std::vector<std::array<glm::vec2, 3>> texel_coordinates;
};

// Texels of gutter on each side of a chart: a bilinear lookup anywhere in the chart reads only
// texels of its own rectangle (derivation in atlas_layout.cpp).
inline constexpr int kGutterTexels = 1;

// Throws gib::InputError when even the smallest charts (one texel plus gutters) do not fit,
// naming the number of charts and the fix (a larger atlas).
AtlasLayout layoutAtlas(const std::vector<AtlasTriangle>& triangles, int resolution);

// One texel of the baked atlas. Row-major, row 0 at the bottom (GL's order): texel (x, y) is
// texels[y * resolution + x].
struct AtlasTexel {
  glm::vec3 position{0.0f};  // sample point in world space
  glm::vec3 normal{0.0f};    // unit; zero outside every chart
  float area = 0;            // world area of surface inside the texel; 0 for gutter and unused
  int triangle = -1;         // index into the triangles; −1 outside every chart
  bool inChart() const { return triangle >= 0; }
};

struct AtlasTexels {
  int resolution = 0;
  std::vector<AtlasTexel> texels;
  int covered = 0;  // texels with area > 0
};

AtlasTexels bakeAtlasTexels(const std::vector<AtlasTriangle>& triangles, const AtlasLayout& layout);

}  // namespace gib::rt::atlas
