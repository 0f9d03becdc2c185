// Radiance seen by the camera: bilinear lookups of the atlas (the reflected estimate and the
// injected direct light) plus the emission, which only the front side of an emitter shows.
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/atlas/atlas_maps.glsl"
#include "realtime/techniques/stochastic_radiosity/stochastic_radiosity_shared.h"

layout(binding = kRadiositySourceUnit) uniform sampler2D u_source;  // L^e plus injected direct light
layout(binding = kRadiosityReflectedUnit) uniform sampler2D u_reflected;  // L̃^r
in vec2 v_atlas_uv;
in vec3 v_world;
flat in vec3 v_normal;
layout(location = 0) out vec4 o_radiance;

void main() {
  vec3 radiance = texture(u_reflected, v_atlas_uv).rgb + texture(u_source, v_atlas_uv).rgb;
  bool front = dot(v_normal, camera.position.xyz - v_world) > 0.0;
  if (!front) radiance -= texture(u_atlas_emission, v_atlas_uv).rgb;
  o_radiance = vec4(max(radiance, vec3(0.0)), 1.0);
}
