#include "realtime/techniques/hemispherical_gather/voxel_slices.h"

#include "realtime/gl/shader_library.h"
#include "realtime/techniques/hemispherical_gather/hemispherical_gather_shared.h"

#include <glm/geometric.hpp>

#include <chrono>

namespace gib::rt {

VoxelSlices::VoxelSlices(const GpuScene& scene, const atlas::AtlasMesh& mesh,
                         const gl::Texture& radiance_atlas, int slices, int size)
    : slices_(slices), size_(size) {
  const auto start = std::chrono::steady_clock::now();
  // A hair beyond the scene's bounds, so that no surface lies on the outermost planes.
  const glm::vec3 pad = 1e-3f * (scene.boundsMax() - scene.boundsMin()) + 1e-6f;
  lo_ = scene.boundsMin() - pad;
  hi_ = scene.boundsMax() + pad;
  gl::LayeredTarget target(GL_RGBA32F, size, kFaces * slices);
  const gl::Framebuffer& framebuffer = target.framebuffer();
  const float empty[4] = {0, 0, 0, 0};
  const float far_depth = 1.0f;
  glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, empty);
  glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &far_depth);

  const gl::Program program = gl::buildProgram(
      {{GL_VERTEX_SHADER, "realtime/techniques/hemispherical_gather/voxelize.vert.glsl"},
       {GL_GEOMETRY_SHADER, "realtime/techniques/hemispherical_gather/gather_view.geom.glsl"},
       {GL_FRAGMENT_SHADER, "realtime/techniques/hemispherical_gather/voxelize.frag.glsl"}});
  const GLuint id = program.id();
  glProgramUniform1i(id, program.uniform("u_slices"), slices);
  glProgramUniform3fv(id, program.uniform("u_bounds_min"), 1, &lo_[0]);
  glProgramUniform3fv(id, program.uniform("u_bounds_max"), 1, &hi_[0]);
  framebuffer.bind();
  glViewport(0, 0, size, size);
  scene.bindSceneBuffers();
  radiance_atlas.bind(gpu::kRadianceAtlasUnit);
  program.use();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  for (int face = 0; face < kFaces; ++face) {
    glProgramUniform1i(id, program.uniform("u_axis"), face / 2);
    glProgramUniform1i(id, program.uniform("u_side"), face % 2);
    glProgramUniform1i(id, program.uniform("u_face"), face);
    mesh.draw(slices);
  }
  faces_ = std::move(target).takeColor();
  glFinish();
  build_ms_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void VoxelSlices::setLookupUniforms(const gl::Program& program) const {
  glProgramUniform1i(program.id(), program.uniform("u_slices"), slices_);
  glProgramUniform3fv(program.id(), program.uniform("u_bounds_min"), 1, &lo_[0]);
  glProgramUniform3fv(program.id(), program.uniform("u_bounds_max"), 1, &hi_[0]);
}

}  // namespace gib::rt
