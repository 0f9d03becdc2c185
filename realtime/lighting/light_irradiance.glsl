// The irradiance light sample k of the batch (point or directional; light_space.glsl) delivers to
// a point, on a plane facing the light, and the direction towards the light. Shared by every
// pass that shades with light samples, so they agree on the spot cone and falloff.
#include "realtime/lighting/light_space.glsl"

// False outside a spot light's cone (no light at all).
bool lightSampleIrradiance(int k, vec3 p, out vec3 wi, out vec3 irradiance) {
#ifdef POINT_LIGHT
  vec4 position = u_light_samples[k].position, axis = u_light_samples[k].axis;
  vec4 intensity = u_light_samples[k].intensity;
  vec3 to_light = position.xyz - p;
  float distance_squared = dot(to_light, to_light);
  wi = to_light * inversesqrt(distance_squared);
  float cos_axis = dot(-wi, axis.xyz);
  if (cos_axis < axis.w) return false;
  float falloff = intensity.w == 0.0 ? 1.0 : pow(max(cos_axis, 0.0), intensity.w);
  // position.w: 0 for a light that is a point; a virtual light that stands for a patch (light
  // path maps) gives the patch's area over π, which keeps its irradiance on a receiver beside it
  // finite (the on-axis irradiance of a disk of that area).
  irradiance = intensity.rgb * (falloff / (distance_squared + position.w));
#else
  wi = -u_light_samples[k].axis.xyz;
  irradiance = u_light_samples[k].intensity.rgb;
#endif
  return true;
}
