// L_indirect (Nijasure et al. 2005, eq. 3-6) of each texel of a G-buffer, added into its target:
// the Lambert lobe around the normal (eq. 6) scaled by the diffuse albedo, and for Phong
// materials the normalised lobe around the mirror direction (eq. 5) scaled by the specular one.
#include "scene/scene.glsl"
#include "techniques/irradiance_volume/irradiance_volume.glsl"

layout(binding = 0) uniform sampler2D u_gbuffer_position;
layout(binding = 1) uniform sampler2D u_gbuffer_normal;
uniform bool u_normals_face_viewer;  // probe views (see shade_light.frag.glsl)
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
    if (dot(n, wo) < 0.0) n = -n;
  }
  vec3 L[SH_MAX_COEFFICIENTS];
  interpolateCoefficients(p, L);
  vec3 radiance = materialDiffuse(material) * zonalTransfer(L, n, u_lambert_factors);
  if (materialIsPhong(material))
    radiance += materialSpecular(material) *
                zonalTransfer(L, reflect(-wo, n), phong_factors[material]);
  o_radiance = vec4(radiance, 0.0);
}
