// `gpu_ray_tracing`: Whitted-style mirror and glass reflection and refraction traced on the GPU
// (book Ch. 5, §5.3 and Figs. 5.7, 5.15), over the shared direct light. The frame is `direct`'s
// (SurfaceLighting: G-buffer, emission, shadow-mapped light samples in batches); after each
// batch's shadow maps, a full-screen pass traces, for every pixel whose visible surface is a
// mirror or glass, the tree of reflected and refracted rays through a GPU ray-casting structure
// (realtime/ray_casting/) up to `max_depth` specular vertices, lighting its diffuse end points
// with that batch's maps: path class L D? S{0,max_depth} E. See README.md beside this file.
#pragma once

#include "realtime/gl/fullscreen_pass.h"
#include "realtime/gl/objects.h"
#include "realtime/lighting/surface_lighting.h"
#include "realtime/ray_casting/gpu_ray_structure.h"
#include "realtime/technique.h"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace gib::rt {

// The trace pass, inside the lights pass (it runs after each batch's shadow maps).
inline constexpr std::string_view kTracePass = "trace";

class GpuRayTracingTechnique final : public Technique {
 public:
  explicit GpuRayTracingTechnique(const ParameterValues& parameters);

  void prepare(const GpuScene& scene, int width, int height) override;
  void render(Frame& frame) override;
  scene::PathClass pathClass() const override;
  std::vector<TechniqueStatistic> statistics() const override;

 private:
  // Every triangle's normals and material in the structure's set order (kTraceTrianglesUnit).
  void uploadTriangles(const scene::Scene& scene, const IvmTriangleSet& set);
  // The ray trees of the specular pixels lit by the batch whose maps are current; the first batch
  // replaces what SurfaceLighting wrote there, the others add.
  void trace(const ShadowMaps& maps, bool first_batch, const RenderTarget& target,
             gl::PassProfiler& profiler);

  SurfaceLighting surface_lighting_;
  int max_depth_;
  std::string structure_name_;
  const GpuScene* scene_ = nullptr;
  std::unique_ptr<GpuRayStructure> structure_;
  gl::Buffer triangle_buffer_;
  gl::Texture triangle_texture_;
  gl::FullScreenPass trace_point_, trace_directional_;
  std::size_t triangle_count_ = 0;
  double structure_build_ms_ = 0;  // the IVM set, the structure's build and upload
};

// The class of a tree `max_depth` specular vertices deep: "LD?S{0,max_depth}E".
std::string gpuRayTracingPathExpression(int max_depth);

TechniqueInfo gpuRayTracingTechniqueInfo();

}  // namespace gib::rt
