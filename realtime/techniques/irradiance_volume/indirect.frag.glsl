// L_indirect (Nijasure et al. 2005, eq. 3-6) of each texel of a G-buffer, added into its target:
// the Lambert lobe around the normal (eq. 6) scaled by the diffuse albedo, and for Phong
// materials the normalised lobe around the mirror direction (eq. 5) scaled by the specular one.
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/techniques/irradiance_volume/irradiance_volume.glsl"
#include "realtime/gbuffer/shaded_surface.glsl"

layout(location = 0) out vec4 o_radiance;

void main() {
  ShadedSurface s;
  if (!shadedSurface(ivec2(gl_FragCoord.xy), s)) discard;
  vec3 L[kShMaxCoefficients];
  interpolateCoefficients(s.p, L);
  vec3 radiance = materialDiffuse(s.material) * zonalTransfer(L, s.n, u_lambert_factors);
  if (materialIsPhong(s.material))
    radiance += materialSpecular(s.material) *
                zonalTransfer(L, reflect(-s.wo, s.n), phong_factors[s.material]);
  o_radiance = vec4(radiance, 0.0);
}
