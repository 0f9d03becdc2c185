// The irradiance light sample k of the batch delivers through its shadow map to a surface point
// with unit normal n (the side it faces): the sample's irradiance on a plane facing it, times
// cos θ and the shadow map's visibility. Shared by every pass that lights points with light
// samples (direct's deferred shading, the atlas passes: first-bounce injection, light path map
// panes; the light path map's entry points), each of which loops over the batch's samples.
#include "realtime/lighting/shadow_lookup.glsl"
#include "realtime/lighting/light_irradiance.glsl"

// False where the sample does not light the point's side (outside a spot's cone, behind the
// surface); else the irradiance and the direction towards the light.
bool shadowedIrradiance(int k, vec3 p, vec3 n, out vec3 wi, out vec3 irradiance) {
  vec3 incident;
  if (!lightSampleIrradiance(k, p, wi, incident)) return false;
  float cos_surface = dot(n, wi);
  if (cos_surface <= 0.0) return false;
  irradiance = incident * (cos_surface * lightVisibility(k, p, n));
  return true;
}

// The sum over the batch of the irradiance on the point's side (diffuse receivers).
vec3 batchIrradiance(vec3 p, vec3 n) {
  vec3 sum = vec3(0.0);
  for (int k = 0; k < u_light_sample_count; ++k) {
    vec3 wi, irradiance;
    if (shadowedIrradiance(k, p, n, wi, irradiance)) sum += irradiance;
  }
  return sum;
}
