#include "realtime/techniques/hemispherical_gather/voxel_slices.h"

#include "realtime/gl/pipeline_state.h"
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
  program.set("u_slices", slices);
  program.set("u_bounds_min", lo_);
  program.set("u_bounds_max", hi_);
  framebuffer.bind();
  scene.bindSceneBuffers();
  radiance_atlas.bind(gpu::kRadianceAtlasUnit);
  program.use();
  {
    // The nearest surface of a slab wins, seen from either side (no culling).
    const gl::PipelineScope state(
        {.depth_test = GL_LESS, .viewport = gl::PixelRect{0, 0, size, size}});
    for (int face = 0; face < kFaces; ++face) {
      program.set("u_axis", face / 2);
      program.set("u_side", face % 2);
      program.set("u_face", face);
      mesh.draw(slices);
    }
  }
  faces_ = std::move(target).takeColor();
  glFinish();
  build_ms_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void VoxelSlices::setLookupUniforms(const gl::Program& program) const {
  program.set("u_slices", slices_);
  program.set("u_bounds_min", lo_);
  program.set("u_bounds_max", hi_);
}

}  // namespace gib::rt
