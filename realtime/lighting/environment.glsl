// The scene's environment map (EnvironmentTexture, book §4.2): the radiance a ray leaving the
// scene receives, with the mapping, rotation and intensity of scene::EnvironmentMap::radiance
// (scene/environment_map.h): a map direction d = (sinθ cosφ, cosθ, sinθ sinφ) lies in texel
// column ⌊φ/(2π)·width⌋ and row ⌊θ/π·height⌋, row 0 the zenith. Needs gpu_scene/scene.glsl
// before it (the camera, for cameraRayThrough).
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gpu_scene/brdf_shared.h"

layout(binding = kEnvironmentUnit) uniform sampler2D u_environment_texels;
// x, y: cosine and sine of the turn about +y from the world into the map's frame
// (EnvironmentMap::toMap); z: the map's intensity.
uniform vec3 u_environment;

// The largest float below 1: latLongCoordinates keeps u and v in [0, 1) so.
const float kEnvironmentBelowOne = 0.99999994;

// EnvironmentMap::toMap: the world direction in the map's frame.
vec3 environmentMapDirection(vec3 world) {
  float c = u_environment.x, s = u_environment.y;
  return vec3(c * world.x + s * world.z, world.y, -s * world.x + c * world.z);
}

// latLongCoordinates: (u, v) = (φ/(2π), θ/π) of a map direction of any length > 0.
vec2 environmentCoordinates(vec3 d) {
  float theta = acos(clamp(d.y / length(d), -1.0, 1.0));
  // atan(0, 0) is undefined in GLSL (C's atan2 gives 0): straight up or down, as the CPU does,
  // take column 0, so that a horizontal surface's normal finds the same texel on every GPU.
  float u = d.x == 0.0 && d.z == 0.0 ? 0.0 : 0.5 * kInvPi * atan(d.z, d.x);  // in [−1/2, 1/2]
  if (u < 0.0) u += 1.0;
  return min(vec2(u, theta * kInvPi), vec2(kEnvironmentBelowOne));
}

// The map's coordinates of a world direction, for lookups in maps laid out as the environment
// (its convolutions).
vec2 environmentCoordinatesOf(vec3 world) {
  return environmentCoordinates(environmentMapDirection(world));
}

// EnvironmentMap::radiance: intensity × the texel the world direction falls in.
vec3 environmentRadiance(vec3 world) {
  ivec2 size = textureSize(u_environment_texels, 0);
  ivec2 texel = min(ivec2(environmentCoordinatesOf(world) * vec2(size)), size - 1);
  return u_environment.z * texelFetch(u_environment_texels, texel, 0).rgb;
}

// The camera ray through a full-screen pass's fragment (gl_FragCoord.xy, the camera image's
// pixel): the direction of the pixel's primary ray, for pixels whose ray leaves the scene.
vec3 cameraRayThrough(vec2 frag_coord) {
  vec2 ndc = 2.0 * frag_coord * camera.image_size.zw - 1.0;
  vec3 view = vec3(ndc.x / camera.projection[0][0], ndc.y / camera.projection[1][1], -1.0);
  return normalize(transpose(mat3(camera.view)) * view);
}
