// The irradiance light sample k of the batch (point or directional; light_space.glsl) delivers to
// a point, on a plane facing the light, and the direction towards the light. Shared by every
// pass that shades with light samples, so they agree on the spot cone and falloff.
#include "realtime/lighting/light_space.glsl"

// False outside a spot light's cone (no light at all).
bool lightSampleIrradiance(int k, vec3 p, out vec3 wi, out vec3 irradiance) {
#ifdef POINT_LIGHT
  wi = normalize(u_light_samples[k].position.xyz - p);
  vec4 lit = pointSampleIrradiance(u_light_samples[k], p);
  irradiance = lit.rgb;
  if (lit.w == 0.0) return false;
#else
  wi = -u_light_samples[k].axis.xyz;
  irradiance = u_light_samples[k].intensity.rgb;
#endif
  return true;
}
