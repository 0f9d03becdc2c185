// The irradiance volume's probes (Nijasure et al. 2005, §4.1): a uniform n×n×n grid over the
// scene's bounds, a probe at the centre of each cell, and their cube maps laid out as tiles of
// one 2D G-buffer ("atlas"), six tiles per probe, so that one deferred pass lights all of them.
#pragma once

#include "realtime/gbuffer/gbuffer.h"
#include "realtime/techniques/irradiance_volume/irradiance_volume_shared.h"
#include "scene/scene.h"

#include <glm/vec3.hpp>

#include <vector>

namespace gib::rt {

struct ProbeGrid {
  int n = 4;               // probes per axis
  int face = 16;           // cube face size in texels
  glm::vec3 origin{0.0f};  // the grid's corner (the scene bounds' minimum)
  glm::vec3 cell{1.0f};    // cell size; probe (x, y, z) sits at origin + (x+½, y+½, z+½)·cell
  int tiles_x = 1;         // tiles per row of the atlas

  int probeCount() const { return n * n * n; }
  int tileCount() const { return gpu::kCubeFaces * probeCount(); }
  int atlasWidth() const { return tiles_x * face; }
  int atlasHeight() const { return ((tileCount() + tiles_x - 1) / tiles_x) * face; }
  // Probe index (z·n + y)·n + x.
  glm::vec3 probePosition(int index) const;
  // The tile of a probe's face: its lower-left texel in the atlas (irradiance_volume_shared.h).
  glm::ivec2 tileOrigin(int probe, int face_index) const {
    return gpu::tileOrigin(gpu::probeTile(probe, face_index), tiles_x, face);
  }

  // The view of every tile, for GBuffer::renderViews.
  std::vector<GBufferView> views(float near_plane, float far_plane) const;
};

// Throws gib::InputError when the atlas of n³ probes with face² cube faces would exceed
// `max_texels`; what makeProbeGrid checks, callable before the scene is known.
void checkProbeAtlasSize(int n, int face, long long max_texels);

// Throws gib::InputError when the atlas would exceed `max_texels` (a grid of 16³ probes with
// 64² faces would need 100 M texels per buffer).
ProbeGrid makeProbeGrid(const glm::vec3& bounds_min, const glm::vec3& bounds_max, int n, int face,
                        long long max_texels);

// The box the grid spans with grid_bounds=objects: an outdoor scene's ground (100 m across in
// `outdoor`) would spread a grid over the scene's bounds so thin that the objects fall between
// probes tens of metres apart. The bounds of every mesh but the one with the largest bounding box
// (the ground, or a room's shell), grown on each side by their own extent along each axis (so that
// a probe next to a lone sphere stands outside it) and kept within the whole scene's bounds. A
// scene of one mesh keeps its bounds.
struct ProbeBounds {
  glm::vec3 min{0.0f}, max{0.0f};
};
ProbeBounds objectsProbeBounds(const scene::Scene& scene);

}  // namespace gib::rt
