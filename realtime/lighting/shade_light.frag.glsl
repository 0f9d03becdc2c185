// Deferred shading of one batch of light samples (point or directional) in one pass, added to
// the frame with additive blending: the sum over the batch of f · (incident irradiance) · cosθ ·
// visibility at each pixel's primary hit (and, with GIB_MEDIUM_TRANSMITTANCE, the particle medium's
// transmittance towards the sample; with GIB_CELL_REFLECTIVITY, environment_shadows' cells by
// their BRDF averaged over each cell, cell_reflectivity.glsl).
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/gpu_scene/brdf.glsl"
#include "realtime/gbuffer/shaded_surface.glsl"
#include "realtime/lighting/shadowed_irradiance.glsl"
#ifdef GIB_MEDIUM_TRANSMITTANCE
#include "realtime/particles/medium_transmittance.glsl"
#endif
#if defined(GIB_CELL_REFLECTIVITY) && !defined(POINT_LIGHT)
#include "realtime/lighting/cell_reflectivity.glsl"
#endif

layout(location = 0) out vec4 o_radiance;

void main() {
  ShadedSurface s;
  if (!shadedSurface(ivec2(gl_FragCoord.xy), s)) discard;
  vec3 p = s.p, n = s.n, wo = s.wo;
  uint material = s.material;
  vec3 diffuse = materialDiffuse(material), specular = materialSpecular(material);
  float exponent = materialExponent(material);
  bool phong = materialIsPhong(material);

  vec3 radiance = vec3(0.0);
  bool lit = false;
  for (int k = 0; k < u_light_sample_count; ++k) {
#if defined(GIB_CELL_REFLECTIVITY) && !defined(POINT_LIGHT)
    // environment_shadows' integrated reflectivity (directional samples only).
    vec3 cell;
    if (cellRadiance(k, p, n, wo, diffuse, specular, exponent, phong, cell)) {
      radiance += cell;
      lit = true;
    }
    continue;
#endif
    vec3 wi, irradiance;
    if (!shadowedIrradiance(k, p, n, wi, irradiance)) continue;
#ifdef GIB_MEDIUM_TRANSMITTANCE
#ifdef POINT_LIGHT
    irradiance *= mediumTransmittance(p, wi, length(u_light_samples[k].position.xyz - p));
#else
    irradiance *= mediumTransmittance(p, wi, 3.0e38);
#endif
#endif
    radiance += evaluateBrdf(diffuse, specular, exponent, phong, n, wo, wi) * irradiance;
    lit = true;
  }
  // Nothing to add where no sample reaches (outside a spot's cone, behind the surface): no blend.
  if (!lit) discard;
  o_radiance = vec4(radiance, 0.0);
}
