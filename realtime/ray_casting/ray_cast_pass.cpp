#include "realtime/ray_casting/ray_cast_pass.h"

#include "realtime/gl/gpu_commands.h"
#include "realtime/gl/shader_library.h"
#include "realtime/ray_casting/ray_cast_pass_shared.h"

namespace gib::rt {

std::vector<CastRay> castRaysOf(const IvmTriangleSet& set, std::span<const scene::Ray> rays) {
  std::vector<CastRay> cast(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    cast[i].origin = ivmRayOrigin(set, rays[i].origin);
    cast[i].direction = rays[i].direction;
  }
  return cast;
}

RayCastPass::RayCastPass(const GpuRayStructure& structure)
    : structure_(&structure),
      program_(gl::buildProgram({{GL_COMPUTE_SHADER, "realtime/ray_casting/cast_rays.comp.glsl"}},
                                structure.castDefines())) {}

void RayCastPass::setRays(const std::vector<CastRay>& rays) {
  count_ = rays.size();
  // A zero-sized buffer cannot be bound; an empty batch still gets one record.
  rays_ = gl::Buffer(std::max<std::size_t>(1, rays.size()) * sizeof(CastRay),
                     rays.empty() ? nullptr : rays.data(), 0);
  hits_ = gl::Buffer(std::max<std::size_t>(1, rays.size()) * sizeof(gpu::RayCastHit), nullptr, 0);
}

void RayCastPass::cast() const {
  if (count_ == 0) return;
  structure_->bind();
  program_.use();
  program_.set("u_ray_count", unsigned(count_));
  rays_.bindBase(GL_SHADER_STORAGE_BUFFER, GLuint(gpu::kCastRaysBinding));
  hits_.bindBase(GL_SHADER_STORAGE_BUFFER, GLuint(gpu::kCastHitsBinding));
  gl::dispatchCompute(GLuint((count_ + gpu::kCastGroupSize - 1) / gpu::kCastGroupSize), 1, 1);
}

std::vector<gpu::RayCastHit> RayCastPass::hits() const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  return gl::readBuffer<gpu::RayCastHit>(hits_, count_);
}

}  // namespace gib::rt
