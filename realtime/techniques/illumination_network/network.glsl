// The network's sizes and directions, read by every pass over its N × D arrays: invocation
// (x, y) is particle p = x and direction i = y.
#include "realtime/techniques/illumination_network/illumination_network_shared.h"

layout(local_size_x = kParticleGroupSize) in;
layout(std430, binding = kSphereDirectionsBinding) readonly buffer Directions {
  vec4 directions[];  // xyz: ω_i, towards where incoming light comes from
};
uniform int u_count;            // N
uniform int u_direction_count;  // D
