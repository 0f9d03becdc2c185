// The object's pixels (book §7.3, eq. 7.8; §4.2.2 with mode=irradiance_map): every other pixel is
// discarded, keeping the shared direct light there; an object's pixel is replaced by the light it
// gathers, which holds its direct light too (the map sees the emitters).
//
// distance_map: every texel of the downsampled map is an area light of the texel's mean radiance
// at its mean distance from o, y = o + L/|L|·distance; its solid angle ω′ from o (eq. 7.7 or 7.6)
// is carried to ω* at x, and it is reflected by the object's BRDF (brdf.glsl: the project's
// normalised Phong, not the book's Blinn-Phong) with cos⁺ at x and no visibility test (with
// GATHER_VISIBILITY, visibility=true, a shadow ray through the scene's BVH to each texel's point).
// irradiance_map: the diffuse irradiance map looked up by the normal, the glossy one by the
// mirror direction R (times cos⁺ at x in direction R, the lobe's peak).
// With CAPTURE_GATHER it also writes the texels each pixel gathered (the `gather` image).
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/gbuffer/gbuffer_maps.glsl"
#include "realtime/gpu_scene/brdf.glsl"
#include "realtime/techniques/distance_map_gather/distance_map_gather_shared.h"
#ifdef GATHER_VISIBILITY
#include "realtime/ray_casting/cast_ray.glsl"
uniform vec3 u_set_origin;   // IvmTriangleSet::origin: rays are cast relative to it
uniform float u_ray_offset;  // kGatherRayOffsetFraction of the scene's diagonal

// Whether anything lies between x and the texel's surface (or, for the sky, on the way out).
bool gatherOccluded(vec3 x, vec3 n, vec3 wi, float distance, bool sky) {
  vec3 origin = x + n * u_ray_offset;
  float reach = sky ? kRayInfinity : distance * (1.0 - kGatherRayShortfall);
  return castRay(origin - u_set_origin, wi, 0.0, reach).t < reach;
}
#endif

layout(binding = kDistanceMapCodeUnit) uniform sampler2D u_codes;  // the camera's GBuffer::albedo
layout(binding = kLowResMapUnit) uniform samplerCubeArray u_low_res;
layout(binding = kIrradianceMapUnit) uniform samplerCubeArray u_irradiance;

uniform ivec2 u_object_triangles;  // first, one past the last
uniform vec3 u_reference_point;    // o
uniform int u_size;                // M
uniform int u_mode;                // kGatherMode…
uniform int u_solid_angle;         // kSolidAngle…
uniform bool u_peak_only;

layout(location = 0) out vec4 o_radiance;
#ifdef CAPTURE_GATHER
layout(location = 1) out vec4 o_texels;  // x: texels gathered, w 1 on the object
#endif

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 position = texelFetch(u_gbuffer_position, pixel, 0);
  if (position.w < 0.0) discard;
  int triangle = int(abs(texelFetch(u_codes, pixel, 0).w)) - 1;
  if (triangle < u_object_triangles.x || triangle >= u_object_triangles.y) discard;
  vec4 normal_material = texelFetch(u_gbuffer_normal, pixel, 0);
  uint material = uint(normal_material.w);
  vec3 x = position.xyz;
  vec3 wo = normalize(camera.position.xyz - x);
  vec3 n = normal_material.xyz;
  if (dot(n, wo) < 0.0) n = -n;  // reflection is two-sided
  vec3 diffuse = materialDiffuse(material), specular = materialSpecular(material);
  float exponent = materialExponent(material);
  bool phong = materialIsPhong(material);
  vec3 mirror = 2.0 * dot(n, wo) * n - wo;

  vec3 radiance = vec3(0.0);
  float texels = 0.0;
  if (u_mode == kGatherFromIrradianceMap) {
    radiance = diffuse * kInvPi * textureLod(u_irradiance, vec4(n, 0.0), 0.0).rgb;
    if (phong)
      radiance += specular * max(dot(n, mirror), 0.0) *
                  textureLod(u_irradiance, vec4(mirror, 1.0), 0.0).rgb;
  } else {
    float peak_cosine = glossyPeakCosine(exponent);
    bool peak_only = u_peak_only && phong;
    for (int face = 0; face < 6; ++face)
      for (int j = 0; j < u_size; ++j)
        for (int i = 0; i < u_size; ++i) {
          // The texel's area light: its direction from o, the surface y it stands for.
          vec3 L = cubeTexelVector(face, i, j, u_size);
          float texel_distance = length(L);
          vec3 direction = L / texel_distance;
          vec4 texel = textureLod(u_low_res, vec4(direction, 0.0), 0.0);
          bool sky = texel.a >= kGatherSkyDistance;
          vec3 to_light = u_reference_point + direction * texel.a - x;
          float shaded_distance = sky ? texel.a : length(to_light);
          vec3 wi = sky ? direction : to_light / shaded_distance;
          // glossy_peak_only: only the texels inside the lobe (the book's Fig. 7.10, lower row).
          if (peak_only && dot(mirror, wi) < peak_cosine) continue;
#ifdef GATHER_VISIBILITY
          // Not the book's: what its omission of this test costs (visibility=true).
          if (dot(n, wi) <= 0.0 || gatherOccluded(x, n, wi, shaded_distance, sky)) continue;
#endif
          // ω′ from o, then ω* from x.
          float omega = texelSolidAngle(texel_distance, u_size, u_solid_angle);
          float omega_x =
              sky ? omega : shadedSolidAngle(omega, texel.a, shaded_distance, u_solid_angle);
          vec3 f = evaluateBrdf(diffuse, specular, exponent, phong, n, wo, wi);
          radiance += texel.rgb * f * max(dot(n, wi), 0.0) * omega_x;
          texels += 1.0;
        }
  }
  o_radiance = vec4(radiance, 1.0);
#ifdef CAPTURE_GATHER
  o_texels = vec4(texels, 0.0, 0.0, 1.0);
#endif
}
