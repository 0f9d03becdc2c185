#include "realtime/techniques/irradiance_cache_splatting/record_sampler.h"

#include "realtime/gl/gpu_commands.h"
#include "realtime/gl/pipeline_state.h"
#include "realtime/gl/shader_library.h"
#include "realtime/techniques/irradiance_cache_splatting/irradiance_cache_splatting_shared.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace gib::rt {

namespace {

// What a batch's views (RGBA32F and 32-bit depth: 20 bytes a texel) may take.
constexpr double kBatchBudgetBytes = 64.0 * 1024 * 1024;
// Distance the views hold where they see nothing: no surface limits the record's zone there.
constexpr float kNoSurfaceDistance = 1e30f;

}  // namespace

RecordSampler::RecordSampler(const RecordSamplingSettings& settings, float extent)
    : settings_(settings) {
  const bool plane = settings.sampling == gpu::kRecordSamplingPlane;
  if (plane && !(settings.plane_fov_degrees > 0 && settings.plane_fov_degrees < 180))
    throw std::invalid_argument("plane sampling needs an aperture between 0 and 180 degrees");
  faces_ = plane ? 1 : gpu::kMaxRecordFaces;
  half_width_ = plane ? std::tan(glm::radians(0.5f * settings.plane_fov_degrees)) : 1.0f;
  const int size = settings.size;
  // A round's record count is not known here: as many layers as the budget and the driver allow.
  const int most_layers = std::numeric_limits<int>::max();
  batch_ =
      std::max(1, gl::layersPerBatch(most_layers, 20.0 * size * size, kBatchBudgetBytes) / faces_);
  views_.emplace(GL_RGBA32F, size, batch_ * faces_);

  const std::string folder = "realtime/techniques/irradiance_cache_splatting/";
  view_program_ = gl::buildProgram({{GL_VERTEX_SHADER, folder + "record_view.vert.glsl"},
                                    {GL_GEOMETRY_SHADER, folder + "record_view.geom.glsl"},
                                    {GL_FRAGMENT_SHADER, folder + "record_view.frag.glsl"}});
  sum_program_ = gl::buildProgram({{GL_COMPUTE_SHADER, folder + "record_sum.comp.glsl"}});
  view_program_.set("u_faces", faces_);
  view_program_.set("u_half_width", half_width_);
  view_program_.set("u_near", 1e-4f * extent);
  view_program_.set("u_far", 2.0f * extent);
  view_program_.set("u_lift", 1e-4f * extent);
  sum_program_.set("u_faces", faces_);
  sum_program_.set("u_size", size);
  sum_program_.set("u_half_width", half_width_);
  sum_program_.set("u_extend_border", plane && settings.extend_border ? 1 : 0);
}

int RecordSampler::pixelsPerRecord() const {
  const int face = settings_.size * settings_.size;
  return faces_ == 1 ? face : face + 4 * (face / 2);
}

void RecordSampler::sample(const GpuScene& scene, const atlas::AtlasMesh& mesh,
                           const gl::Texture& radiance_atlas, const gl::Buffer& records, int first,
                           int count, gl::PassProfiler& profiler, const glm::vec3& background) {
  records.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kRecordsBinding);
  for (int begin = first; begin < first + count; begin += batch_) {
    const int n = std::min(batch_, first + count - begin);
    {
      auto pass = profiler.pass(kRecordViewsPass);
      // The nearest surface wins, both sides of every surface hiding what is behind them (no
      // culling); what lies below the record's tangent plane is clipped (record_view.vert.glsl).
      const gl::PipelineScope state({
          .depth_test = GL_LESS,
          .clip_distances = 1,
          .viewport = gl::PixelRect{0, 0, settings_.size, settings_.size},
      });
      const float clear[4] = {background.r, background.g, background.b, kNoSurfaceDistance};
      const float far_depth = 1.0f;
      const gl::Framebuffer& framebuffer = views_->framebuffer();
      glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, clear);
      glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &far_depth);
      framebuffer.bind();
      scene.bindSceneBuffers();
      radiance_atlas.bind(gpu::kSplatRadianceAtlasUnit);
      view_program_.use();
      view_program_.set("u_first_record", begin);
      mesh.draw(n * faces_);
    }
    auto pass = profiler.pass(kRecordSumsPass);
    sum_program_.use();
    sum_program_.set("u_first_record", begin);
    views_->color().bind(gpu::kRecordViewsUnit);
    gl::dispatchCompute(GLuint(n), 1, 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                    GL_BUFFER_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  }
}

}  // namespace gib::rt
