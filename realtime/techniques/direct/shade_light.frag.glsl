// Deferred shading of one light sample (point or directional), added to the frame with additive
// blending: f · (incident irradiance) · cosθ · visibility at each pixel's primary hit.
#include "scene/scene.glsl"
#include "shaders/phong_brdf.glsl"
#include "techniques/direct/shadow_lookup.glsl"

layout(binding = 0) uniform sampler2D u_gbuffer_position;  // xyz world, w ray distance (−1: none)
layout(binding = 1) uniform sampler2D u_gbuffer_normal;    // xyz geometric normal, w material
uniform vec3 u_light_intensity;
uniform float u_cos_cone;
uniform float u_exponent;
// Probe views (GBuffer::renderViews) store normals turned towards their own eye, which this pass
// does not know: it then takes ωo along the normal, exact for Lambert surfaces and, for Phong,
// the lobe's value at normal viewing (an approximation the irradiance volume accepts).
uniform bool u_normals_face_viewer;
layout(location = 0) out vec4 o_radiance;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 position = texelFetch(u_gbuffer_position, pixel, 0);
  if (position.w < 0.0) discard;
  vec4 normal_material = texelFetch(u_gbuffer_normal, pixel, 0);
  uint material = uint(normal_material.w);
  vec3 p = position.xyz;
  vec3 n = normal_material.xyz;
  vec3 wo = n;
  if (!u_normals_face_viewer) {
    wo = normalize(camera.position.xyz - p);
    if (dot(n, wo) < 0.0) n = -n;  // reflection is two-sided
  }

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
