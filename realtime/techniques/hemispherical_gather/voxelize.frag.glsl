// A slab's face: the first surface inside slab `gl_Layer mod slices` seen from the face's side
// (depth-tested), its once-reflected radiance from the radiance atlas, alpha 1.
#include "realtime/techniques/hemispherical_gather/hemispherical_gather_shared.h"

layout(binding = kRadianceAtlasUnit) uniform sampler2D u_radiance_atlas;
uniform int u_axis;
uniform int u_slices;
uniform vec3 u_bounds_min;
uniform vec3 u_bounds_max;
in vec2 v_atlas_uv;
in vec3 v_world;
flat in vec3 v_normal;
layout(location = 0) out vec4 o_radiance;

void main() {
  float t = (v_world[u_axis] - u_bounds_min[u_axis]) / (u_bounds_max[u_axis] - u_bounds_min[u_axis]);
  int slab = gl_Layer % u_slices;
  if (t < float(slab) / float(u_slices) || t >= float(slab + 1) / float(u_slices)) discard;
  o_radiance = vec4(texture(u_radiance_atlas, v_atlas_uv).rgb, 1.0);
}
