#include "realtime/techniques/irradiance_volume/probe_grid.h"

#include "common/input_error.h"
#include "realtime/cube_faces.h"

#include <fmt/format.h>

#include <cmath>

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

}  // namespace gib::rt
