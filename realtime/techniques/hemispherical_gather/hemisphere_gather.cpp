#include "realtime/techniques/hemispherical_gather/hemisphere_gather.h"

#include "realtime/gl/gpu_commands.h"
#include "realtime/gl/pipeline_state.h"
#include "realtime/gl/shader_library.h"
#include "realtime/techniques/hemispherical_gather/hemispherical_gather_shared.h"
#include "realtime/techniques/hemispherical_gather/voxel_slices.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gib::rt {

namespace {

// What a batch's views (RGBA32F and 32-bit depth: 20 bytes a texel) may take.
constexpr double kBatchBudgetBytes = 128.0 * 1024 * 1024;

// The box around a gather point whose geometry the voxel-slice view draws itself: the point's
// voxel grown by half a voxel on each side ("we expand a little the volume", §5.3).
glm::vec3 nearBox(const VoxelSlices& slices) {
  return 1.5f * (slices.boundsMax() - slices.boundsMin()) / float(slices.slices());
}

}  // namespace

HemisphereGather::HemisphereGather(int projection, int view_size, int spacing, int width,
                                   int height, float extent)
    : projection_(projection), view_size_(view_size), spacing_(spacing), extent_(extent) {
  grid_ = {(width + spacing - 1) / spacing, (height + spacing - 1) / spacing};
  batch_ = gl::layersPerBatch(grid_.x * grid_.y, 20.0 * view_size * view_size, kBatchBudgetBytes);
  views_.emplace(GL_RGBA32F, view_size, batch_);
  irradiance_ = gl::Texture::make2D(GL_RGBA32F, grid_.x, grid_.y);
  irradiance_.setFilter(GL_NEAREST, GL_NEAREST);
  const float zero[4] = {0, 0, 0, 0};
  glClearTexImage(irradiance_.id(), 0, GL_RGBA, GL_FLOAT, zero);

  view_program_ = gl::buildProgram(
      {{GL_VERTEX_SHADER, "realtime/techniques/hemispherical_gather/gather_view.vert.glsl"},
       {GL_GEOMETRY_SHADER, "realtime/techniques/hemispherical_gather/gather_view.geom.glsl"},
       {GL_FRAGMENT_SHADER, "realtime/techniques/hemispherical_gather/gather_view.frag.glsl"}});
  sum_program_ = gl::buildProgram(
      {{GL_COMPUTE_SHADER, "realtime/techniques/hemispherical_gather/gather_sum.comp.glsl"}});
  setPointUniforms(view_program_);
  view_program_.set("u_projection", projection);
  view_program_.set("u_near", 1e-4f * extent);
  view_program_.set("u_far", 2.0f * extent);
  sum_program_.set("u_grid", grid_);
  sum_program_.set("u_size", view_size);
  sum_program_.set("u_projection", projection);
  if (projection == gpu::kProjectionVoxelSlices) {
    slices_program_ = gl::buildProgram(
        {{GL_VERTEX_SHADER, "realtime/techniques/hemispherical_gather/gather_slices.vert.glsl"},
         {GL_GEOMETRY_SHADER, "realtime/techniques/hemispherical_gather/gather_view.geom.glsl"},
         {GL_FRAGMENT_SHADER, "realtime/techniques/hemispherical_gather/gather_slices.frag.glsl"}});
    setPointUniforms(slices_program_);
    slices_program_.set("u_size", view_size);
    slices_program_.set("u_near", 1e-4f * extent);
    slices_program_.set("u_far", 2.0f * extent);
  }
}

void HemisphereGather::setPointUniforms(const gl::Program& program) const {
  program.set("u_grid", grid_);
  program.set("u_spacing", spacing_);
  program.set("u_lift", 1e-4f * extent_);
  program.set("u_normals_face_viewer", 0);
}

void HemisphereGather::gather(const GpuScene& scene, const atlas::AtlasMesh& mesh,
                              const gl::Texture& radiance_atlas, const GBuffer& gbuffer,
                              gl::PassProfiler& profiler, const glm::vec3& background,
                              const VoxelSlices* slices) {
  if (projection_ == gpu::kProjectionVoxelSlices && !slices)
    throw std::logic_error("the voxel-slice projection needs the slices");
  const int clip_distances =
      projection_ == gpu::kProjectionVoxelSlices ? gpu::kGatherClipDistances : 1;
  if (slices) {
    view_program_.set("u_near_box", nearBox(*slices));
    slices_program_.set("u_near_box", nearBox(*slices));
    slices->setLookupUniforms(slices_program_);
  }
  auto pass = profiler.pass(kGatherPass);
  // The nearest surface wins, both sides of every surface hiding what is behind them (no
  // culling); the views' geometry is clipped, and the slices are depth-tested against it.
  const gl::PipelineState depth_tested = {.depth_test = GL_LESS,
                                          .viewport = gl::PixelRect{0, 0, view_size_, view_size_}};
  gl::PipelineState clipped = depth_tested;
  clipped.clip_distances = clip_distances;
  const int points = grid_.x * grid_.y;
  for (int first = 0; first < points; first += batch_) {
    const int count = std::min(batch_, points - first);
    {
      auto views = profiler.pass(kGatherViewsPass);
      const gl::PipelineScope state(clipped);
      const float clear[4] = {background.r, background.g, background.b, 0};
      const float far_depth = 1.0f;
      const gl::Framebuffer& framebuffer = views_->framebuffer();
      glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, clear);
      glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &far_depth);
      framebuffer.bind();
      scene.bindSceneBuffers();
      gbuffer.bindTextures();
      radiance_atlas.bind(gpu::kRadianceAtlasUnit);
      view_program_.use();
      view_program_.set("u_first_point", first);
      mesh.draw(count);
    }
    if (slices) {
      // Beyond the near box, the slices: one full-layer triangle per point, depth-tested
      // against the near geometry.
      auto traced = profiler.pass(kGatherSlicesPass);
      const gl::PipelineScope state(depth_tested);
      slices->faces().bind(gpu::kVoxelSlicesUnit);
      slices_program_.use();
      slices_program_.set("u_first_point", first);
      empty_vertex_array_.bind();
      gl::drawArraysInstanced(GL_TRIANGLES, 0, 3, count);
    }
    auto sum = profiler.pass(kGatherSumPass);
    sum_program_.use();
    sum_program_.set("u_first_point", first);
    views_->color().bind(gpu::kGatherViewsUnit);
    glBindImageTexture(gpu::kImageDestinationUnit, irradiance_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                       GL_RGBA32F);
    gl::dispatchCompute(GLuint(count), 1, 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  }
}

}  // namespace gib::rt
