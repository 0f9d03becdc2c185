#include "realtime/techniques/gpu_ray_tracing/gpu_ray_tracing_technique.h"

#include "realtime/gl/finished_time.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/pipeline_state.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/ray_casting/ivm_triangles.h"
#include "realtime/ray_casting/ray_structures.h"
#include "realtime/render_target.h"
#include "realtime/techniques/gpu_ray_tracing/gpu_ray_tracing_shared.h"
#include "scene/path_expression.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

namespace gib::rt {

namespace {

// The structure a frame casts through unless told otherwise: the BVH, the fastest of the
// factory's here (the spheres box at 512²: trace 228 ms against the loose kd-tree's 353 ms,
// README.md beside this file).
constexpr const char* kDefaultStructure = "bvh";

}  // namespace

std::string gpuRayTracingPathExpression(int max_depth) {
  return fmt::format("LD?S{{0,{}}}E", max_depth);
}

GpuRayTracingTechnique::GpuRayTracingTechnique(const ParameterValues& p)
    : surface_lighting_(p),
      max_depth_(p.integer("max_depth")),
      structure_name_(p.text("structure")) {}

scene::PathClass GpuRayTracingTechnique::pathClass() const {
  return scene::PathClass::ofExpression(
      scene::PathExpression::parse(gpuRayTracingPathExpression(max_depth_)).text());
}

void GpuRayTracingTechnique::prepare(const GpuScene& scene, int width, int height) {
  scene_ = &scene;
  surface_lighting_.prepare(scene, width, height);

  // The structure over every triangle, timed to the end of its upload.
  IvmTriangleSet set;
  structure_build_ms_ = gl::finishedMilliseconds([&] {
    set = buildIvmTriangles(scene.scene());
    structure_ = makeGpuRayStructure(structure_name_, set);
    uploadTriangles(scene.scene(), set);
  });
  triangle_count_ = set.size();

  // One program per kind of light sample, as the shadow maps' lookups differ.
  const ShadowMaps& maps = surface_lighting_.lighting().shadowMaps();
  const float diagonal = glm::length(scene.boundsMax() - scene.boundsMin());
  auto build = [&](LightSampleKind kind) {
    gl::FullScreenPass pass("realtime/techniques/gpu_ray_tracing/trace.frag.glsl",
                            maps.defines(kind) + structure_->castDefines() +
                                fmt::format("#define MAX_DEPTH {}\n", max_depth_));
    maps.setLookupConstants(pass.program());
    pass.program().set("u_set_origin", glm::vec3(set.origin));
    pass.program().set("u_ray_offset", gpu::kTraceRayOffsetFraction * diagonal);
    pass.program().set("u_sky_radiance", glm::vec3(scene.scene().sky_radiance));
    return pass;
  };
  trace_point_ = build(LightSampleKind::kPoint);
  trace_directional_ = build(LightSampleKind::kDirectional);
}

void GpuRayTracingTechnique::uploadTriangles(const scene::Scene& scene, const IvmTriangleSet& set) {
  std::vector<glm::vec4> texels(set.size() * gpu::kTraceTriangleTexels, glm::vec4(0.0f));
  for (std::size_t i = 0; i < set.size(); ++i) {
    const IvmTriangle& t = set.triangles[i];
    const scene::Mesh& mesh = scene.meshes[t.mesh];
    const glm::uvec3& v = mesh.triangles[t.triangle];
    const glm::dvec3 a(mesh.positions[v.x]), b(mesh.positions[v.y]), c(mesh.positions[v.z]);
    glm::vec4* record = &texels[i * gpu::kTraceTriangleTexels];
    record[0] =
        glm::vec4(glm::vec3(glm::normalize(glm::cross(b - a, c - a))), float(mesh.material));
    if (mesh.normals.empty()) continue;  // flat: zero shading normals
    for (int k = 0; k < 3; ++k) record[1 + k] = glm::vec4(mesh.normals[v[k]], 0.0f);
  }
  triangle_buffer_ = gl::Buffer(texels.size() * sizeof(glm::vec4), texels.data(), 0);
  triangle_texture_ = gl::Texture::makeBuffer(GL_RGBA32F, triangle_buffer_);
}

void GpuRayTracingTechnique::render(Frame& frame) {
  gl::PassProfiler& profiler = frame.profiler;
  surface_lighting_.drawSurfaces(*scene_, frame.target, profiler);
  // Traced again after every batch (one with the default light samples on the built-in scenes);
  // README.md beside this file says why the tree is not stored between batches.
  bool first_batch = true;
  surface_lighting_.addDirect(*scene_, &frame.target, profiler, {}, [&](const ShadowMaps& maps) {
    trace(maps, first_batch, frame.target, profiler);
    first_batch = false;
  });
}

void GpuRayTracingTechnique::trace(const ShadowMaps& maps, bool first_batch,
                                   const RenderTarget& target, gl::PassProfiler& profiler) {
  auto pass = profiler.pass(kTracePass);
  const gl::FullScreenPass& p =
      maps.batchKind() == LightSampleKind::kPoint ? trace_point_ : trace_directional_;
  p.use();
  scene_->bindSceneBuffers();
  surface_lighting_.gbuffer().bindTextures();
  maps.bindForLookup(p.program());
  structure_->bind();
  triangle_texture_.bind(gpu::kTraceTrianglesUnit);
  p.program().set("u_first_batch", first_batch ? 1 : 0);
  // The first batch's tree replaces what the pixel held (SurfaceLighting's emission and light of
  // the specular surface itself, which its shading treats as a black diffuse one); later batches
  // add their light.
  const gl::PipelineScope scope(first_batch ? gl::PipelineState{}
                                            : gl::PipelineState{.blend = gl::kAdditiveBlend});
  target.bind();
  p.draw();
}

std::vector<TechniqueStatistic> GpuRayTracingTechnique::statistics() const {
  return {{"ray_triangles", double(triangle_count_)},
          {"structure_mb", structure_ ? double(structure_->bytes()) / (1024.0 * 1024.0) : 0.0},
          {"prepare_structure_ms", structure_build_ms_}};
}

TechniqueInfo gpuRayTracingTechniqueInfo() {
  TechniqueInfo info;
  info.name = "gpu_ray_tracing";
  info.description =
      "Whitted-style mirror and glass reflection and refraction traced on the GPU through a "
      "ray-casting structure, over the shared direct light";
  info.source =
      "Szirmay-Kalos et al., GPU-Based Techniques for Global Illumination Effects, §5.3 and Figs. "
      "5.7, 5.15";
  info.parameters = joinParameterTables(
      {{numericParameter("max_depth", ParameterType::kInteger, "4", 1, gpu::kMaxTraceDepth, "",
                         "specular vertices a path may have (the k of L D? S{0,k} E): the ray "
                         "tree's depth"),
        choiceParameter("structure", kDefaultStructure, gpuRayStructureNames(),
                        "the GPU ray-casting structure the rays are cast through (book Ch. 5)")},
       SurfaceLighting::parameters()});
  SurfaceLighting::declarePasses(info.passes);
  info.passes.add(passPath({kFramePass, kLightsPass, kTracePass}),
                  "per batch: the mirror and glass pixels' ray trees, their end points lit by the "
                  "batch");
  info.statistics = {
      {"ray_triangles", "triangles the structure holds (those with area)"},
      {"structure_mb", "GPU memory of the structure's data, MiB"},
      {"prepare_structure_ms", "building and uploading the structure and the triangle records"}};
  info.needs = {TechniqueNeed::kSpecularMaterials};
  info.create = [](const ParameterValues& values) -> std::unique_ptr<Technique> {
    return std::make_unique<GpuRayTracingTechnique>(values);
  };
  return info;
}

}  // namespace gib::rt
