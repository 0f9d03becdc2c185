// Deferred shading of one light sample (point or directional), added to the frame with additive
// blending: f · (incident irradiance) · cosθ · visibility at each pixel's primary hit.
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/gpu_scene/brdf.glsl"
#include "realtime/gbuffer/shaded_surface.glsl"
#include "realtime/lighting/shadowed_irradiance.glsl"

layout(location = 0) out vec4 o_radiance;

void main() {
  ShadedSurface s;
  if (!shadedSurface(ivec2(gl_FragCoord.xy), s)) discard;
  vec3 p = s.p, n = s.n, wo = s.wo;
  uint material = s.material;

  vec3 wi, irradiance;
  if (!shadowedIrradiance(p, n, wi, irradiance)) discard;
  vec3 f = evaluateBrdf(materialDiffuse(material), materialSpecular(material),
                        materialExponent(material), materialIsPhong(material), n, wo, wi);
  o_radiance = vec4(f * irradiance, 0.0);
}
