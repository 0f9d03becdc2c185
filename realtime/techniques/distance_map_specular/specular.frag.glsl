// The camera's mirror and glass pixels (book §6.2): each traces its reflected (and a glass's
// refracted) ray through its object's distance map and shows what the map holds there, weighted
// by Fresnel's function; every other pixel is discarded, keeping the shared direct light there.
// With CAPTURE_SEARCH it also writes the ray whose search the error image measures and the hit
// the search found (DistanceMapSpecularTechnique::auxiliaryImages).
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/gbuffer/gbuffer_maps.glsl"
#include "realtime/distance_map/distance_map.glsl"
#include "realtime/distance_map/specular_radiance.glsl"

layout(binding = kDistanceMapCodeUnit) uniform sampler2D u_codes;  // the camera's GBuffer::albedo

layout(location = 0) out vec4 o_radiance;
#ifdef CAPTURE_SEARCH
layout(location = 1) out vec4 o_hit;  // xyz the hit the search found (world), w 1
layout(location = 2) out vec4 o_ray;  // xyz the traced ray's direction, w its object's index
#endif

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 position = texelFetch(u_gbuffer_position, pixel, 0);
  if (position.w < 0.0) discard;
  vec4 normal_material = texelFetch(u_gbuffer_normal, pixel, 0);
  uint material = uint(normal_material.w);
  int type = materialType(material);
  if (type != kMaterialMirror && type != kMaterialGlass) discard;
  int object = distanceMapObjectOf(int(abs(texelFetch(u_codes, pixel, 0).w)) - 1);
  if (object < 0) discard;
  vec3 traced_ray, traced_hit;
  vec3 radiance = distanceMapSpecular(object, material, position.xyz, normal_material.xyz,
                                      camera.position.xyz, traced_ray, traced_hit);
  o_radiance = vec4(radiance, 1.0);
#ifdef CAPTURE_SEARCH
  o_hit = vec4(traced_hit, 1.0);
  o_ray = vec4(traced_ray, float(object));
#endif
}
