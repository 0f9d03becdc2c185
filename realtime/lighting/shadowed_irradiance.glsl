// The irradiance the current light sample delivers through its shadow map to a surface point
// with unit normal n (the side it faces): the sample's irradiance on a plane facing it, times
// cos θ and the shadow map's visibility. Shared by every pass that lights points with light
// samples: direct's deferred shading, the atlas passes (first-bounce injection, light path map
// panes) and the light path map's entry points.
#include "realtime/lighting/shadow_lookup.glsl"
#include "realtime/lighting/light_irradiance.glsl"

// False where the sample does not light the point's side (outside a spot's cone, behind the
// surface); else the irradiance and the direction towards the light.
bool shadowedIrradiance(vec3 p, vec3 n, out vec3 wi, out vec3 irradiance) {
  vec3 incident;
  if (!lightSampleIrradiance(p, wi, incident)) return false;
  float cos_surface = dot(n, wi);
  if (cos_surface <= 0.0) return false;
  irradiance = incident * (cos_surface * lightVisibility(p, n));
  return true;
}
