// One round of composing the distance maps (book §6.1, §6.3) from their views, which the
// G-buffer holds as tiles (object k's face f at tile (f, k), N × N texels each): per texel, the
// sky where the view sees nothing, else the surface's emission from its front side, the direct
// light the shared lighting added into the views, and, on a mirror or glass of another object,
// what that object's map of the previous round shows it (the rounds of §6.3: the first round's
// previous maps are black, so each round adds one specular bounce). Writes rgb radiance and the
// surface's distance from the map's reference point, layer 6k + f of the array.
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/gbuffer/gbuffer_maps.glsl"
#include "realtime/distance_map/distance_map.glsl"
#include "realtime/distance_map/specular_radiance.glsl"

layout(local_size_x = kDistanceMapGroupSize, local_size_y = kDistanceMapGroupSize) in;

layout(binding = kDistanceMapLightUnit) uniform sampler2D u_view_light;
layout(binding = kDistanceMapCodeUnit) uniform sampler2D u_view_codes;  // GBuffer::albedo
layout(binding = kImageDestinationUnit, rgba32f) uniform writeonly imageCubeArray u_destination;

uniform vec3 u_sky_radiance;

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  int size = u_distance_map.counts.y;
  int face = texel.x / size, object = texel.y / size;
  if (face >= 6 || object >= u_distance_map.counts.x) return;
  ivec3 destination = ivec3(texel.x % size, texel.y % size, 6 * object + face);

  vec4 position = texelFetch(u_gbuffer_position, texel, 0);
  if (position.w < 0.0) {
    imageStore(u_destination, destination, vec4(u_sky_radiance, kDistanceMapNoSurface));
    return;
  }
  vec4 normal_material = texelFetch(u_gbuffer_normal, texel, 0);
  uint material = uint(normal_material.w);
  float code = texelFetch(u_view_codes, texel, 0).w;
  vec3 radiance = texelFetch(u_view_light, texel, 0).rgb;
  if (code > 0.0) radiance += materialEmission(material);
  int type = materialType(material);
  if (type == kMaterialMirror || type == kMaterialGlass) {
    int owner = distanceMapObjectOf(int(abs(code)) - 1);
    vec3 traced_ray, traced_hit;
    if (owner >= 0)
      radiance += distanceMapSpecular(owner, material, position.xyz, normal_material.xyz,
                                      distanceMapReferencePoint(object), traced_ray, traced_hit);
  }
  imageStore(u_destination, destination, vec4(radiance, position.w));
}
