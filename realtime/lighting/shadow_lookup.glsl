// Visibility of light sample k of the batch from a world point through its shadow map (book
// §4.1.2–4.1.3): a depth comparison (hard: nearest texel; PCF: the hardware's bilinearly filtered
// comparison, the book's 2×2 PCF, over a (2r+1)² grid of taps one texel apart), or for a variance
// shadow map the one-tailed Chebyshev bound σ²/(σ² + (z − E[Z])²), taken as 1 when z ≤ E[Z].
// The batch's maps are one array texture; sample k's is layer k (a batch of one point sample:
// one cube map).
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/lighting/light_space.glsl"

// The map's sampler types, moments (VSM) and depth comparison, and how a cube lookup names its
// sample's cube: a batch of one point sample has one cube map (shadow_maps.cpp), more a
// cube-map array.
#ifdef POINT_LIGHT
#ifdef SINGLE_CUBE_MAP
#define MOMENTS_SAMPLER samplerCube
#define DEPTH_SAMPLER samplerCubeShadow
#define CUBE_MOMENTS(v, layer) texture(u_shadow_map, v)
#define CUBE_COMPARE(v, layer, depth) texture(u_shadow_map, vec4(v, depth))
#else
#define MOMENTS_SAMPLER samplerCubeArray
#define DEPTH_SAMPLER samplerCubeArrayShadow
#define CUBE_MOMENTS(v, layer) texture(u_shadow_map, vec4(v, layer))
#define CUBE_COMPARE(v, layer, depth) texture(u_shadow_map, vec4(v, layer), depth)
#endif
#else
#define MOMENTS_SAMPLER sampler2DArray
#define DEPTH_SAMPLER sampler2DArrayShadow
#endif
#ifdef VARIANCE_SHADOW_MAP
layout(binding = kShadowMapUnit) uniform MOMENTS_SAMPLER u_shadow_map;
#else
layout(binding = kShadowMapUnit) uniform DEPTH_SAMPLER u_shadow_map;
#endif

uniform int u_shadow_map_size;
uniform float u_ortho_extent;   // directional: world width of the map
uniform float u_normal_offset;  // in texels, against acne
uniform int u_pcf_radius;
uniform float u_min_variance;

// World size of one shadow-map texel at p: 90° cube faces span 2·distance along the major axis.
float texelWorldSize(int k, vec3 p) {
#ifdef POINT_LIGHT
  vec3 v = abs(p - u_light_samples[k].position.xyz);
  return 2.0 * max(v.x, max(v.y, v.z)) / float(u_shadow_map_size);
#else
  return u_ortho_extent / float(u_shadow_map_size);
#endif
}

float chebyshevUpperBound(vec2 moments, float z) {
  if (z <= moments.x) return 1.0;
  float variance = max(moments.y - moments.x * moments.x, u_min_variance);
  float d = z - moments.x;
  return variance / (variance + d * d);
}

float shadowTap(int k, vec3 p) {
  float layer = float(k);
#ifdef POINT_LIGHT
  vec3 v = p - u_light_samples[k].position.xyz;
#ifdef VARIANCE_SHADOW_MAP
  return chebyshevUpperBound(CUBE_MOMENTS(v, layer).rg, lightDistance(k, p));
#else
  // The window depth the cube face selected by v stored for this point.
  float major = max(abs(v.x), max(abs(v.y), abs(v.z)));
  float ndc = (u_far + u_near) / (u_far - u_near) - 2.0 * u_far * u_near / ((u_far - u_near) * major);
  return CUBE_COMPARE(v, layer, ndc * 0.5 + 0.5);
#endif
#else
  vec3 c = (u_light_samples[k].view_projection * vec4(p, 1.0)).xyz * 0.5 + 0.5;
#ifdef VARIANCE_SHADOW_MAP
  return chebyshevUpperBound(texture(u_shadow_map, vec3(c.xy, layer)).rg, c.z);
#else
  return texture(u_shadow_map, vec4(c.xy, layer, c.z));
#endif
#endif
}

// `n` is the surface normal on the side facing the light.
float lightVisibility(int k, vec3 p, vec3 n) {
  float texel = texelWorldSize(k, p);
  vec3 q = p + n * (u_normal_offset * texel);
  if (u_pcf_radius == 0) return shadowTap(k, q);
#ifdef POINT_LIGHT
  vec3 d = normalize(q - u_light_samples[k].position.xyz);
#else
  vec3 d = u_light_samples[k].axis.xyz;
#endif
  vec3 t = normalize(abs(d.x) > 0.9 ? cross(d, vec3(0.0, 1.0, 0.0)) : cross(d, vec3(1.0, 0.0, 0.0)));
  vec3 b = cross(d, t);
  float sum = 0.0;
  for (int j = -u_pcf_radius; j <= u_pcf_radius; ++j)
    for (int i = -u_pcf_radius; i <= u_pcf_radius; ++i)
      sum += shadowTap(k, q + (float(i) * t + float(j) * b) * texel);
  float side = float(2 * u_pcf_radius + 1);
  return sum / (side * side);
}
