// What every particle pass reads (particle_medium.h): the particles, the phase table, the
// directional lights, the albedo and the sky.
#include "realtime/particles/particle_shared.h"

layout(std430, binding = kParticlesBinding) readonly buffer Particles {
  GpuParticle particles[];
};
layout(binding = kPhaseTableUnit) uniform sampler2D u_phase_table;

uniform int u_light_count;
uniform vec3 u_light_direction[kMaxParticleLights];   // propagation direction
uniform vec3 u_light_irradiance[kMaxParticleLights];  // W/m² across the beam
uniform vec3 u_albedo;
uniform vec3 u_sky;

// The phase function from its table; cos θ between propagation directions.
float phase(float cos_theta) {
  return texture(u_phase_table, vec2(phaseTableCoordinate(cos_theta), 0.5)).r;
}
