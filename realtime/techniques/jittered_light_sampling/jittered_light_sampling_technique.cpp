#include "realtime/techniques/jittered_light_sampling/jittered_light_sampling_technique.h"

#include "realtime/gl/gpu_commands.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/shader_library.h"
#include "realtime/technique_parameters.h"
#include "realtime/techniques/jittered_light_sampling/jittered_light_sampling_shared.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace gib::rt {

namespace {

constexpr std::string_view kAreaLightsPass = "area lights";
constexpr std::string_view kCoveragePass = "coverage";
constexpr std::string_view kWeighingPass = "weighing";
// What a batch's coverage layers (8-bit) and their depth (32-bit) may take (5 bytes a texel).
constexpr double kBatchBudgetBytes = 64.0 * 1024 * 1024;

CoverageSettings coverageSettings(const ParameterValues& p) {
  CoverageSettings s;
  const std::string& scheme = p.text("scheme");
  parseCoverageScheme(scheme == "jittered" ? "jittered" + p.text("samples_per_pixel") : scheme, s);
  s.size = p.integer("sampling_size");
  s.seed = std::uint32_t(p.integer("seed"));
  return s;
}

// The scene's triangles but those in the light's own plane (the light itself, and surfaces flush
// with it, which cannot hide it), three corners each.
std::vector<glm::vec4> occludersOf(const scene::Scene& scene, const AreaLight& light,
                                   float tolerance) {
  std::vector<glm::vec4> corners;
  const glm::vec3 p0 = light.triangles.front();
  auto inPlane = [&](const glm::vec3& p) {
    return std::abs(glm::dot(p - p0, light.normal)) < tolerance;
  };
  for (const scene::Mesh& mesh : scene.meshes)
    for (const glm::uvec3& t : mesh.triangles) {
      const glm::vec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
      if (inPlane(a) && inPlane(b) && inPlane(c)) continue;
      corners.insert(corners.end(), {glm::vec4(a, 1), glm::vec4(b, 1), glm::vec4(c, 1)});
    }
  return corners;
}

}  // namespace

JitteredLightSamplingTechnique::JitteredLightSamplingTechnique(const ParameterValues& p)
    : coverage_(coverageSettings(p)), surface_lighting_(p, /*area_lights=*/false) {}

void JitteredLightSamplingTechnique::prepare(const GpuScene& scene, int width, int height) {
  scene_ = &scene;
  surface_lighting_.prepare(scene, width, height);
  const float extent = glm::length(scene.boundsMax() - scene.boundsMin());
  lights_ = groupAreaLights(scene.emitters(), extent);
  lift_ = 1e-5f * extent;
  points_ = width * height;

  batch_ = gl::layersPerBatch(points_, 5.0 * coverage_.size * coverage_.size, kBatchBudgetBytes);
  coverage_layers_.emplace(GL_R8UI, coverage_.size, batch_);

  draw_program_ = gl::buildProgram(
      {{GL_VERTEX_SHADER, "realtime/techniques/jittered_light_sampling/coverage.vert.glsl"},
       {GL_GEOMETRY_SHADER, "realtime/techniques/jittered_light_sampling/coverage.geom.glsl"},
       {GL_FRAGMENT_SHADER, "realtime/techniques/jittered_light_sampling/coverage.frag.glsl"}},
      "#define GBUFFER_POINTS\n");
  weigh_program_ =
      gl::buildProgram({{GL_COMPUTE_SHADER,
                         "realtime/techniques/jittered_light_sampling/weigh_coverage.comp.glsl"}});
  const int samples =
      coverage_.scheme == CoverageScheme::kJittered ? coverage_.samples_per_pixel : 0;
  for (const gl::Program* program : {&draw_program_, &weigh_program_}) {
    program->set("u_point_count", points_);
    program->set("u_gbuffer_width", width);
    program->set("u_lift", lift_);
    program->set("u_normals_face_viewer", 0);
    program->set("u_size", coverage_.size);
    program->set("u_samples", samples);
    program->set("u_seed", coverage_.seed);
  }
  weigh_program_.set("u_equal_weights",
                     coverage_.scheme == CoverageScheme::kOcclusionQuery ? 1 : 0);

  // Per light, its triangles then its occluders.
  for (const AreaLight& light : lights_) {
    std::vector<glm::vec4> corners;
    for (const glm::vec3& c : light.triangles) corners.emplace_back(c, 1.0f);
    const std::vector<glm::vec4> occluders = occludersOf(scene.scene(), light, 1e-4f * extent);
    corners.insert(corners.end(), occluders.begin(), occluders.end());
    light_buffers_.push_back(gl::Buffer::fromVector(corners, 0));
  }
}

void JitteredLightSamplingTechnique::render(Frame& frame) {
  const GpuScene& scene = *scene_;
  surface_lighting_.drawSurfaces(scene, frame.target, frame.profiler);
  if (surface_lighting_.lighting().sampleCount() > 0)
    surface_lighting_.addDirect(scene, &frame.target, frame.profiler);
  if (lights_.empty()) return;
  auto pass = frame.profiler.pass(kAreaLightsPass);
  for (std::size_t i = 0; i < lights_.size(); ++i) sampleAreaLight(i, frame.target, frame.profiler);
}

void JitteredLightSamplingTechnique::sampleAreaLight(std::size_t index, const RenderTarget& target,
                                                     gl::PassProfiler& profiler) {
  const AreaLight& light = lights_[index];
  const gl::Buffer& triangles = light_buffers_[index];
  const auto light_vertices = GLsizei(light.triangles.size());
  const auto all_vertices = GLsizei(triangles.bytes() / sizeof(glm::vec4));
  for (const gl::Program* program : {&draw_program_, &weigh_program_}) {
    program->set("u_light_vertices", light_vertices);
    program->set("u_emitting_side", light.normal);
  }
  weigh_program_.set("u_emission", light.emission);
  scene_->bindSceneBuffers();
  surface_lighting_.gbuffer().bindTextures();
  triangles.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kCoverageTrianglesBinding);

  for (int first = 0; first < points_; first += batch_) {
    const int count = std::min(batch_, points_ - first);
    {
      auto coverage = profiler.pass(kCoveragePass);
      draw_program_.use();
      draw_program_.set("u_first_point", first);
      vertex_array_.bind();
      drawCoverage(coverage_layers_->framebuffer(), coverage_.size, light_vertices, all_vertices,
                   count);
    }
    auto weighing = profiler.pass(kWeighingPass);
    weigh_program_.use();
    weigh_program_.set("u_first_point", first);
    coverage_layers_->color().bind(gpu::kCoverageUnit);
    glBindImageTexture(gpu::kImageDestinationUnit, target.color().id(), 0, GL_FALSE, 0,
                       GL_READ_WRITE, GL_RGBA32F);
    gl::dispatchCompute(GLuint(count), 1, 1);
    // The next batch's weighing reads what this one added; the harness reads the target.
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                    GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  }
}

std::vector<TechniqueStatistic> JitteredLightSamplingTechnique::statistics() const {
  return {{"points", double(points_)},
          {"area_lights", double(lights_.size())},
          {"points_per_batch", double(batch_)}};
}

TechniqueInfo jitteredLightSamplingTechniqueInfo() {
  TechniqueInfo info;
  info.name = "jittered_light_sampling";
  info.description =
      "direct illumination (LE|LDE) with area lights sampled by rasterizing the light and its "
      "occluders from every pixel: occlusion query, regular or jittered (1, 4, 8 per pixel)";
  info.source =
      "Fournier & Péroche, Speeding up global illumination computations using programmable "
      "GPUs, §4";
  info.parameters = joinParameterTables(
      {{
           choiceParameter(
               "scheme", "jittered", {"occlusion_query", "regular", "jittered"},
               "how the coverage image samples the light: visible pixel centres counted "
               "alike, pixel centres weighted by their solid angle, or jittered samples"),
           integerChoiceParameter("samples_per_pixel", 1, {1, 4, 8}, "",
                                  "jittered: samples per pixel, one in each stratum (2×2, 4×2)"),
           numericParameter("sampling_size", ParameterType::kInteger, "32", kMinCoverageSize,
                            kMaxCoverageSize, "pixels",
                            "coverage image side, per point and light (the paper: 32, 48, 64)"),
           seedParameter("seed of the jittered sample positions"),
       },
       SurfaceLighting::parameters()});
  SurfaceLighting::declarePasses(info.passes);
  const std::string area = passPath({kFramePass, kAreaLightsPass});
  info.passes.add(area, "per area light, per batch of points: coverage, then weighing");
  info.passes.add(passPath({area, kCoveragePass}),
                  "the light and its occluders rasterized into each point's coverage layer");
  info.passes.add(passPath({area, kWeighingPass}),
                  "each point's visible samples weighed by solid angle, BRDF and cosine");
  info.statistics = {
      {"points", "shading points lit by the area lights"},
      {"area_lights", "area lights sampled by rasterization"},
      {"points_per_batch", "points whose coverage images are drawn at once"},
  };
  info.create = [](const ParameterValues& values) -> std::unique_ptr<Technique> {
    return std::make_unique<JitteredLightSamplingTechnique>(values);
  };
  return info;
}

}  // namespace gib::rt
