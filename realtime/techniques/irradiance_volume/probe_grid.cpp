#include "realtime/techniques/irradiance_volume/probe_grid.h"

#include "common/input_error.h"
#include "realtime/cube_faces.h"

#include <fmt/format.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace gib::rt {

glm::vec3 ProbeGrid::probePosition(int index) const {
  const int x = index % n, y = (index / n) % n, z = index / (n * n);
  return origin + (glm::vec3(float(x), float(y), float(z)) + 0.5f) * cell;
}

std::vector<GBufferView> ProbeGrid::views(float near_plane, float far_plane) const {
  std::vector<GBufferView> result;
  result.reserve(std::size_t(tileCount()));
  for (int probe = 0; probe < probeCount(); ++probe) {
    const glm::vec3 eye = probePosition(probe);
    for (int f = 0; f < gpu::kCubeFaces; ++f) {
      const glm::ivec2 tile = tileOrigin(probe, f);
      result.push_back(
          {cubeFaceViewProjection(eye, f, near_plane, far_plane), eye, tile.x, tile.y, face, face});
    }
  }
  return result;
}

namespace {

ProbeGrid layout(int n, int face) {
  ProbeGrid grid;
  grid.n = n;
  grid.face = face;
  grid.tiles_x = int(std::ceil(std::sqrt(double(grid.tileCount()))));
  return grid;
}

}  // namespace

void checkProbeAtlasSize(int n, int face, long long max_texels) {
  const ProbeGrid grid = layout(n, face);
  const long long texels = (long long)grid.atlasWidth() * grid.atlasHeight();
  if (texels > max_texels)
    throw InputError(fmt::format(
        "grid={} with face={} needs {} cube-map texels, more than {}; lower grid or face", n, face,
        texels, max_texels));
}

ProbeGrid makeProbeGrid(const glm::vec3& bounds_min, const glm::vec3& bounds_max, int n, int face,
                        long long max_texels) {
  checkProbeAtlasSize(n, face, max_texels);
  ProbeGrid grid = layout(n, face);
  grid.origin = bounds_min;
  grid.cell = (bounds_max - bounds_min) / float(n);
  return grid;
}

namespace {

ProbeBounds emptyBounds() {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  return {glm::vec3(kInf), glm::vec3(-kInf)};
}

ProbeBounds meshBounds(const scene::Mesh& mesh) {
  ProbeBounds b = emptyBounds();
  for (const glm::vec3& p : mesh.positions) {
    b.min = glm::min(b.min, p);
    b.max = glm::max(b.max, p);
  }
  return b;
}

void grow(ProbeBounds& b, const ProbeBounds& other) {
  b.min = glm::min(b.min, other.min);
  b.max = glm::max(b.max, other.max);
}

}  // namespace

ProbeBounds objectsProbeBounds(const scene::Scene& scene) {
  ProbeBounds all = emptyBounds();
  std::size_t largest = 0;
  float largest_diagonal = -1.0f;
  std::vector<ProbeBounds> meshes;
  for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
    meshes.push_back(meshBounds(scene.meshes[i]));
    grow(all, meshes.back());
    const float diagonal = glm::length(meshes.back().max - meshes.back().min);
    if (diagonal > largest_diagonal) {
      largest_diagonal = diagonal;
      largest = i;
    }
  }
  if (meshes.size() < 2) return all;
  ProbeBounds objects = emptyBounds();
  for (std::size_t i = 0; i < meshes.size(); ++i)
    if (i != largest) grow(objects, meshes[i]);
  const glm::vec3 extent = objects.max - objects.min;
  return {glm::max(objects.min - extent, all.min), glm::min(objects.max + extent, all.max)};
}

}  // namespace gib::rt
