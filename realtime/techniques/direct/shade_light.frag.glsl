// Deferred shading of one light sample (point or directional), added to the frame with additive
// blending: f · (incident irradiance) · cosθ · visibility at each pixel's primary hit.
#include "scene/scene.glsl"
#include "shaders/phong_brdf.glsl"
#include "techniques/direct/shadow_lookup.glsl"
#include "shaders/shaded_surface.glsl"

uniform vec3 u_light_intensity;
uniform float u_cos_cone;
uniform float u_exponent;
layout(location = 0) out vec4 o_radiance;

void main() {
  ShadedSurface s;
  if (!shadedSurface(ivec2(gl_FragCoord.xy), s)) discard;
  vec3 p = s.p, n = s.n, wo = s.wo;
  uint material = s.material;

#ifdef POINT_LIGHT
  vec3 to_light = u_light_position - p;
  float distance_squared = dot(to_light, to_light);
  vec3 wi = to_light * inversesqrt(distance_squared);
  float cos_axis = dot(-wi, u_light_axis);
  if (cos_axis < u_cos_cone) discard;
  float falloff = u_exponent == 0.0 ? 1.0 : pow(max(cos_axis, 0.0), u_exponent);
  vec3 irradiance = u_light_intensity * (falloff / distance_squared);
#else
  vec3 wi = -u_light_axis;
  vec3 irradiance = u_light_intensity;
#endif
  float cos_surface = dot(n, wi);
  if (cos_surface <= 0.0) discard;
  vec3 f = evaluateBrdf(materialDiffuse(material), materialSpecular(material),
                        materialExponent(material), materialIsPhong(material), n, wo, wi);
  o_radiance = vec4(f * irradiance * (cos_surface * lightVisibility(p, n)), 0.0);
}
