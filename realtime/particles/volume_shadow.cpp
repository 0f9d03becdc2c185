#include "realtime/particles/volume_shadow.h"

#include "realtime/gl/gpu_commands.h"
#include "realtime/gl/shader_library.h"
#include "realtime/particles/particle_shared.h"

namespace gib::rt {

VolumeShadow::VolumeShadow()
    : program_(
          gl::buildProgram({{GL_COMPUTE_SHADER, "realtime/particles/volume_shadow.comp.glsl"}})) {}

void VolumeShadow::compute(const ParticleMedium& medium, const gl::Buffer& directions,
                           int direction_count, gl::Buffer& transmittance) const {
  const std::size_t bytes = std::size_t(medium.count()) * std::size_t(direction_count) * 4;
  if (transmittance.bytes() < bytes) transmittance = gl::Buffer(bytes, nullptr);
  if (direction_count == 0) return;
  medium.bind();
  directions.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kSphereDirectionsBinding);
  transmittance.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kTransmittanceBinding);
  program_.set("u_count", medium.count());
  program_.set("u_direction_count", direction_count);
  program_.use();
  gl::dispatchCompute(
      GLuint((medium.count() + gpu::kParticleGroupSize - 1) / gpu::kParticleGroupSize),
      GLuint(direction_count), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace gib::rt
