#include "realtime/techniques/hemispherical_gather/hemisphere_gather.h"

#include "realtime/gl/gpu_commands.h"
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

void setUniform(const gl::Program& program, const char* name, int value) {
  glProgramUniform1i(program.id(), program.uniform(name), value);
}
void setUniform(const gl::Program& program, const char* name, float value) {
  glProgramUniform1f(program.id(), program.uniform(name), value);
}
void setUniform(const gl::Program& program, const char* name, glm::ivec2 value) {
  glProgramUniform2i(program.id(), program.uniform(name), value.x, value.y);
}
void setUniform(const gl::Program& program, const char* name, glm::vec3 value) {
  glProgramUniform3fv(program.id(), program.uniform(name), 1, &value[0]);
}

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
  setUniform(view_program_, "u_projection", projection);
  setUniform(view_program_, "u_near", 1e-4f * extent);
  setUniform(view_program_, "u_far", 2.0f * extent);
  setUniform(sum_program_, "u_grid", grid_);
  setUniform(sum_program_, "u_size", view_size);
  setUniform(sum_program_, "u_projection", projection);
  if (projection == gpu::kProjectionVoxelSlices) {
    slices_program_ = gl::buildProgram(
        {{GL_VERTEX_SHADER, "realtime/techniques/hemispherical_gather/gather_slices.vert.glsl"},
         {GL_GEOMETRY_SHADER, "realtime/techniques/hemispherical_gather/gather_view.geom.glsl"},
         {GL_FRAGMENT_SHADER, "realtime/techniques/hemispherical_gather/gather_slices.frag.glsl"}});
    setPointUniforms(slices_program_);
    setUniform(slices_program_, "u_size", view_size);
    setUniform(slices_program_, "u_near", 1e-4f * extent);
    setUniform(slices_program_, "u_far", 2.0f * extent);
  }
}

void HemisphereGather::setPointUniforms(const gl::Program& program) const {
  setUniform(program, "u_grid", grid_);
  setUniform(program, "u_spacing", spacing_);
  setUniform(program, "u_lift", 1e-4f * extent_);
  setUniform(program, "u_normals_face_viewer", 0);
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
    setUniform(view_program_, "u_near_box", nearBox(*slices));
    setUniform(slices_program_, "u_near_box", nearBox(*slices));
    slices->setLookupUniforms(slices_program_);
  }
  auto pass = profiler.pass(kGatherPass);
  const int points = grid_.x * grid_.y;
  for (int first = 0; first < points; first += batch_) {
    const int count = std::min(batch_, points - first);
    {
      auto views = profiler.pass(kGatherViewsPass);
      const float clear[4] = {background.r, background.g, background.b, 0};
      const float far_depth = 1.0f;
      const gl::Framebuffer& framebuffer = views_->framebuffer();
      glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, clear);
      glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &far_depth);
      framebuffer.bind();
      glViewport(0, 0, view_size_, view_size_);
      scene.bindSceneBuffers();
      gbuffer.bindTextures();
      radiance_atlas.bind(gpu::kRadianceAtlasUnit);
      view_program_.use();
      setUniform(view_program_, "u_first_point", first);
      glEnable(GL_DEPTH_TEST);
      glDepthFunc(GL_LESS);
      glDepthMask(GL_TRUE);
      glDisable(GL_CULL_FACE);  // both sides of every surface hide what is behind them
      glDisable(GL_BLEND);
      for (int i = 0; i < clip_distances; ++i) glEnable(GL_CLIP_DISTANCE0 + i);
      mesh.draw(count);
      for (int i = 0; i < clip_distances; ++i) glDisable(GL_CLIP_DISTANCE0 + i);
    }
    if (slices) {
      // Beyond the near box, the slices: one full-layer triangle per point, depth-tested
      // against the near geometry.
      auto traced = profiler.pass(kGatherSlicesPass);
      slices->faces().bind(gpu::kVoxelSlicesUnit);
      slices_program_.use();
      setUniform(slices_program_, "u_first_point", first);
      empty_vertex_array_.bind();
      gl::drawArraysInstanced(GL_TRIANGLES, 0, 3, count);
    }
    auto sum = profiler.pass(kGatherSumPass);
    sum_program_.use();
    setUniform(sum_program_, "u_first_point", first);
    views_->color().bind(gpu::kGatherViewsUnit);
    glBindImageTexture(gpu::kImageDestinationUnit, irradiance_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                       GL_RGBA32F);
    gl::dispatchCompute(GLuint(count), 1, 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  }
}

}  // namespace gib::rt
