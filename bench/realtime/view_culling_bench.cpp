// What per-view culling costs the CPU each frame (realtime/gpu_scene/view_culling.h): the records
// of the irradiance volume's 384 probe cube faces (a 4³ grid through the scene's bounds) over the
// chamber's chunks, at 64 triangles a chunk (the default) and at 16.
#include "realtime/cube_faces.h"
#include "realtime/gpu_scene/view_culling.h"
#include "scene/builtin_scenes.h"

#include <benchmark/benchmark.h>

#include <vector>

namespace {

using namespace gib;

void BM_ViewCullingRecords(benchmark::State& state) {
  const scene::Scene chamber = scene::loadScene("chamber", {});
  std::vector<glm::vec3> positions;
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const scene::Mesh& mesh : chamber.meshes)
    for (const glm::uvec3& t : mesh.triangles)
      for (unsigned i : {t.x, t.y, t.z}) {
        positions.push_back(mesh.positions[i]);
        lo = glm::min(lo, positions.back());
        hi = glm::max(hi, positions.back());
      }
  const std::vector<rt::TriangleChunk> chunks = rt::triangleChunks(positions, int(state.range(0)));
  std::vector<glm::mat4> views;
  for (int p = 0; p < 64; ++p) {
    const glm::vec3 cell((float(p % 4) + 0.5f) / 4.0f, (float(p / 4 % 4) + 0.5f) / 4.0f,
                         (float(p / 16) + 0.5f) / 4.0f);
    for (int face = 0; face < 6; ++face)
      views.push_back(rt::cubeFaceViewProjection(lo + cell * (hi - lo), face, 0.01f, 40.0f));
  }
  std::vector<rt::DrawArraysIndirectCommand> records;
  for (auto _ : state) {
    records.clear();
    for (std::size_t v = 0; v < views.size(); ++v)
      rt::appendVisibleRuns(chunks, views[v], GLuint(v % 16), records);
    benchmark::DoNotOptimize(records.data());
  }
  state.counters["chunks"] = double(chunks.size());
  state.counters["records"] = double(records.size());
}
BENCHMARK(BM_ViewCullingRecords)->Arg(64)->Arg(16)->Unit(benchmark::kMicrosecond);

}  // namespace
