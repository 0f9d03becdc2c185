// The transmittance of the particle medium from a surface point towards a light sample, for the
// surface shading of the particle techniques (DirectLighting::setShadingDefines with
// GIB_MEDIUM_TRANSMITTANCE): exp(−Σ optical depth) of every particle's chord along the segment
// from p towards the light (to its position for a point sample, to infinity for a directional
// one). N particles per pixel and sample: meant for the book's thousands of particles.
#include "realtime/particles/particle_shared.h"

layout(std430, binding = kParticlesBinding) readonly buffer MediumParticles {
  GpuParticle medium_particles[];
};

float mediumTransmittance(vec3 p, vec3 wi, float distance) {
  float depth = 0.0;
  for (int q = 0; q < medium_particles.length(); ++q)
    depth += particleSegmentDepth(medium_particles[q], p, wi, distance);
  return exp(-depth);
}
