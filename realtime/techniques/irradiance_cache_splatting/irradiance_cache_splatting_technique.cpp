#include "realtime/techniques/irradiance_cache_splatting/irradiance_cache_splatting_technique.h"

#include "common/elapsed.h"
#include "realtime/gl/gpu_commands.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/pipeline_state.h"
#include "realtime/gl/shader_library.h"
#include "realtime/irradiance_cache/irradiance_cache_parameters.h"
#include "realtime/irradiance_cache/zone_illustration.h"
#include "realtime/technique_parameters.h"
#include "realtime/techniques/irradiance_cache_splatting/irradiance_cache_splatting_shared.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>

namespace gib::rt {

namespace {

constexpr std::string_view kRecordsPass = "records";
constexpr std::string_view kRecordDetectionPass = "record detection";
constexpr std::string_view kRecordSamplingPass = "record sampling";
constexpr std::string_view kSplatPass = "splatting";
constexpr std::string_view kNormalizePass = "normalisation";

using Clock = std::chrono::steady_clock;

// The notes' first step on the CPU: the G-buffer's positions and normals read back, normals
// turned to the viewer as the splatting's fragments turn them (shaded_surface.glsl).
SurfaceImage readSurfaces(const GBuffer& gbuffer, const glm::vec3& eye) {
  SurfaceImage s;
  s.width = gbuffer.width();
  s.height = gbuffer.height();
  const std::size_t count = std::size_t(s.width) * std::size_t(s.height);
  std::vector<glm::vec4> position(count), normal(count);
  glGetTextureImage(gbuffer.position().id(), 0, GL_RGBA, GL_FLOAT,
                    GLsizei(count * sizeof(glm::vec4)), position.data());
  glGetTextureImage(gbuffer.normal().id(), 0, GL_RGBA, GL_FLOAT, GLsizei(count * sizeof(glm::vec4)),
                    normal.data());
  s.position.resize(count);
  s.normal.resize(count);
  s.valid.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    s.valid[i] = position[i].w >= 0 ? 1 : 0;
    s.position[i] = glm::vec3(position[i]);
    glm::vec3 n(normal[i]);
    if (glm::dot(n, eye - s.position[i]) < 0) n = -n;
    s.normal[i] = n;
  }
  return s;
}

int samplingOf(const ParameterValues& p) {
  return p.text("sampling") == "hemicube" ? gpu::kRecordSamplingHemicube
                                          : gpu::kRecordSamplingPlane;
}

}  // namespace

IrradianceCacheSplattingTechnique::IrradianceCacheSplattingTechnique(const ParameterValues& p)
    : placement_(recordPlacementSettings(p)),
      atlas_resolution_(p.integer("atlas")),
      light_samples_(p.integer("light_samples")),
      reuse_records_(p.boolean("reuse_records")),
      surface_lighting_(p) {
  sampling_.sampling = samplingOf(p);
  sampling_.size = p.integer("sample_size");
  sampling_.plane_fov_degrees = float(p.number("plane_fov"));
  sampling_.extend_border = p.boolean("border_compensation");
}

void IrradianceCacheSplattingTechnique::prepare(const GpuScene& scene, int width, int height) {
  scene_ = &scene;
  surface_lighting_.prepare(scene, width, height);
  const float extent = std::max(glm::length(scene.boundsMax() - scene.boundsMin()), 1e-6f);
  atlas_ = atlas::makeDirectRadianceAtlas(scene, atlas_resolution_, light_samples_);
  mesh_.emplace(atlas_.triangles, atlas_.layout, 0);  // perspective views keep edges straight
  sampler_.emplace(sampling_, extent);
  sums_ = gl::Texture::make2D(GL_RGBA32F, width, height);
  sums_.setFilter(GL_NEAREST, GL_NEAREST);
  sums_target_.attachColor(0, sums_);
  sums_target_.setDrawBuffers(1);
  sums_target_.checkComplete();
  const std::string folder = "realtime/techniques/irradiance_cache_splatting/";
  splat_program_ = gl::buildProgram({{GL_VERTEX_SHADER, folder + "record_splat.vert.glsl"},
                                     {GL_FRAGMENT_SHADER, folder + "record_splat.frag.glsl"}});
  splat_program_.set("u_accuracy", placement_.accuracy);
  normalize_ = gl::FullScreenPass(folder + "record_normalize.frag.glsl");
  // The cache of the first frame (the notes: ~20 s, then ~1 s per frame reusing it), timed by the
  // statistics; frames rebuild it only without reuse.
  surface_lighting_.gbuffer().render(scene);
  gl::PassProfiler unmeasured;  // passes outside a frame are no-ops
  buildRecords(unmeasured);
}

void IrradianceCacheSplattingTechnique::render(Frame& frame) {
  const GpuScene& scene = *scene_;
  surface_lighting_.render(scene, frame.target, frame.profiler);
  if (!reuse_records_) buildRecords(frame.profiler);
  splat(frame);
}

void IrradianceCacheSplattingTechnique::buildRecords(gl::PassProfiler& profiler) {
  const GpuScene& scene = *scene_;
  auto pass = profiler.pass(kRecordsPass);
  const auto start = Clock::now();
  detection_ms_ = sampling_ms_ = 0;
  records_.clear();
  {
    auto detection = profiler.pass(kRecordDetectionPass);
    const auto t = Clock::now();
    surfaces_ = readSurfaces(surface_lighting_.gbuffer(), scene.camera().position);
    detection_ms_ += millisecondsSince(t);
  }
  RecordPlacement placement(surfaces_, scene.camera(), placement_);
  for (;;) {
    std::vector<glm::ivec2> round;
    {
      auto detection = profiler.pass(kRecordDetectionPass);
      const auto t = Clock::now();
      round = placement.nextRound();
      detection_ms_ += millisecondsSince(t);
    }
    if (round.empty()) break;
    std::vector<gpu::IrradianceRecord> fresh(round.size());
    for (std::size_t i = 0; i < round.size(); ++i) {
      const std::size_t pixel = surfaces_.index(round[i].x, round[i].y);
      fresh[i].position_radius = glm::vec4(surfaces_.position[pixel], 0.0f);
      fresh[i].normal = glm::vec4(surfaces_.normal[pixel], 0.0f);
    }
    const std::size_t bytes = fresh.size() * sizeof(gpu::IrradianceRecord);
    {
      auto sampling = profiler.pass(kRecordSamplingPass);
      const auto t = Clock::now();
      if (round_buffer_.bytes() < bytes) round_buffer_ = gl::Buffer(2 * bytes, nullptr);
      round_buffer_.update(0, bytes, fresh.data());
      sampler_->sample(scene, *mesh_, atlas_.radiance, round_buffer_, 0, int(fresh.size()),
                       profiler);
      // The notes read each record back to splat its weight on the CPU: the traversal waits.
      glGetNamedBufferSubData(round_buffer_.id(), 0, GLsizeiptr(bytes), fresh.data());
      sampling_ms_ += millisecondsSince(t);
    }
    {
      auto detection = profiler.pass(kRecordDetectionPass);
      const auto t = Clock::now();
      placement.add(fresh);
      detection_ms_ += millisecondsSince(t);
    }
    records_.insert(records_.end(), fresh.begin(), fresh.end());
  }
  rounds_ = placement.rounds();
  if (!records_.empty()) records_buffer_ = gl::Buffer::fromVector(records_);
  records_ms_ = millisecondsSince(start);
}

void IrradianceCacheSplattingTechnique::replaceRecords(std::vector<gpu::IrradianceRecord> records) {
  records_ = std::move(records);
  if (!records_.empty()) records_buffer_ = gl::Buffer::fromVector(records_);
}

void IrradianceCacheSplattingTechnique::splat(Frame& frame) {
  const GpuScene& scene = *scene_;
  {
    auto pass = frame.profiler.pass(kSplatPass);
    const float zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(sums_target_.id(), GL_COLOR, 0, zero);
    if (!records_.empty()) {
      sums_target_.bind();
      const gl::PipelineScope adding({
          .blend = gl::kAdditiveBlend,
          .viewport = gl::PixelRect{0, 0, sums_.width(), sums_.height()},
      });
      scene.bindSceneBuffers();
      surface_lighting_.gbuffer().bindTextures();
      records_buffer_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kRecordsBinding);
      splat_program_.use();
      empty_vertex_array_.bind();
      gl::drawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(records_.size()));
    }
  }
  auto pass = frame.profiler.pass(kNormalizePass);
  sums_.bind(gpu::kSplatSumsUnit);
  surface_lighting_.gbuffer().albedo().bind(gpu::kSplatAlbedoUnit);
  frame.target.bind();
  const gl::PipelineScope adding({.blend = gl::kAdditiveBlend});
  normalize_.draw();
}

std::vector<AuxiliaryImage> IrradianceCacheSplattingTechnique::auxiliaryImages() {
  image::Image sums = gl::readTexture(sums_, 4);
  image::Image irradiance(sums.width(), sums.height(), 3);
  for (int y = 0; y < sums.height(); ++y)
    for (int x = 0; x < sums.width(); ++x) {
      const float* s = sums.pixel(x, y);
      float* e = irradiance.pixel(x, y);
      for (int c = 0; c < 3; ++c) e[c] = s[3] > 0 ? s[c] / s[3] : 0.0f;
    }
  return {zonesAuxiliaryImage(surfaces_, scene_->camera(), records_, placement_.accuracy),
          {"irradiance", "the splatted irradiance E = Σ w·E_k / Σ w (before ρ/π)",
           std::move(irradiance)}};
}

std::vector<TechniqueStatistic> IrradianceCacheSplattingTechnique::statistics() const {
  const double records = double(records_.size());
  return {{"records", records},
          {"record_rounds", double(rounds_)},
          {"pixels_per_record", double(sampler_ ? sampler_->pixelsPerRecord() : 0)},
          {"records_per_batch", double(sampler_ ? sampler_->recordsPerBatch() : 0)},
          {"records_ms", records_ms_},
          {"record_detection_ms", detection_ms_},
          {"record_sampling_ms", sampling_ms_},
          {"records_per_second", records_ms_ > 0 ? 1e3 * records / records_ms_ : 0.0},
          {"prepare_atlas_ms", atlas_.milliseconds}};
}

TechniqueInfo irradianceCacheSplattingTechniqueInfo() {
  TechniqueInfo info;
  info.name = "irradiance_cache_splatting";
  info.description =
      "direct light plus one bounce (up to LDDE) from Ward's irradiance cache on the GPU: "
      "records by rasterized hemisphere sampling, interpolation by splatting their zones";
  info.source =
      "SIGGRAPH 2008 course notes, Irradiance cache splatting and GPU hemisphere sampling";
  info.parameters = joinParameterTables(
      {irradianceCacheParameters(),
       {
           choiceParameter("sampling", "plane", {"plane", "hemicube"},
                           "record hemisphere rasterized by one wide camera with the notes' border "
                           "compensation, or by the five faces of a hemicube"),
           numericParameter("sample_size", ParameterType::kInteger, "64", 4, 1024, "pixels",
                            "side of each sampling image (the plane's, or each hemicube face's)"),
           numericParameter("plane_fov", ParameterType::kNumber, "126.87", 10, 179, "degrees",
                            "plane sampling's aperture; Larsen et al.'s 126.87° sees 86% of the "
                            "directions (notes 001)"),
           booleanParameter(
               "border_compensation", true,
               "plane sampling: border pixels also stand for the directions beyond them"),
           atlasParameter(256,
                          "radiance atlas texels per side (the directly lit scene the views see)"),
       },
       SurfaceLighting::parameters()});
  SurfaceLighting::declarePasses(info.passes);
  const std::string records = passPath({kFramePass, kRecordsPass});
  info.passes.add(records,
                  "the cache built (the first frame, or every frame without reuse), round by "
                  "round");
  info.passes.add(passPath({records, kRecordDetectionPass}),
                  "CPU: the G-buffer read back, the traversal's uncovered pixels, and each new "
                  "record's weight splatted over its zone");
  const std::string sampling = passPath({records, kRecordSamplingPass});
  info.passes.add(sampling, "the round's records computed on the GPU and read back");
  info.passes.add(passPath({sampling, kRecordViewsPass}),
                  "the directly lit scene rasterized around each record, a layer per face");
  info.passes.add(passPath({sampling, kRecordSumsPass}),
                  "each record's views summed: irradiance, harmonic mean distance, gradients");
  info.passes.add(passPath({kFramePass, kSplatPass}),
                  "every record's zone drawn as a screen-aligned quad: (w·E, w) blended");
  info.passes.add(passPath({kFramePass, kNormalizePass}),
                  "Σ w·E / Σ w times ρ/π added to the frame");
  info.auxiliary_images = {
      zonesImageDeclaration(),
      {"irradiance", "the splatted irradiance E = Σ w·E_k / Σ w (before ρ/π)"},
  };
  info.statistics = irradianceCacheStatistics({
      {"pixels_per_record", "pixels of each record's sampling images"},
      {"records_per_batch", "records whose hemispheres are rasterized at once"},
      {"record_detection_ms", "CPU time finding the pixels that need a record"},
      {"record_sampling_ms", "time of the records' GPU hemisphere sampling"},
      {"prepare_atlas_ms", "time to build the directly lit radiance atlas"},
  });
  info.create = [](const ParameterValues& values) -> std::unique_ptr<Technique> {
    return std::make_unique<IrradianceCacheSplattingTechnique>(values);
  };
  return info;
}

}  // namespace gib::rt
