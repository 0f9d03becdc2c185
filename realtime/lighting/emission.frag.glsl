// Paths with no bounce: emitters seen directly (one-sided, from their front) and the sky where
// the primary ray leaves the scene: its constant radiance, or with ENVIRONMENT_MAP the
// environment map's texel in the ray's direction.
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/gbuffer/gbuffer_maps.glsl"
#ifdef ENVIRONMENT_MAP
#include "realtime/lighting/environment.glsl"
#else
uniform vec3 u_sky_radiance;
#endif
layout(location = 0) out vec4 o_radiance;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 position = texelFetch(u_gbuffer_position, pixel, 0);
  if (position.w < 0.0) {
#ifdef ENVIRONMENT_MAP
    o_radiance = vec4(environmentRadiance(cameraRayThrough(gl_FragCoord.xy)), 1.0);
#else
    o_radiance = vec4(u_sky_radiance, 1.0);
#endif
    return;
  }
  vec4 normal_material = texelFetch(u_gbuffer_normal, pixel, 0);
  bool front = dot(normal_material.xyz, camera.position.xyz - position.xyz) > 0.0;
  vec3 emission = materialEmission(uint(normal_material.w));
  o_radiance = vec4(front ? emission : vec3(0.0), 1.0);
}
