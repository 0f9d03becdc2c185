// The light of directional sample k over its environment cell with the integrated reflectivity
// (book §4.2.3: v(x, ω_i)·Ψ_i·a(Δω_i, ω)), the cell a cap of half-angle position.w around the
// sample's direction (cell_reflectivity_shared.h). Visibility is still the one shadow-map lookup
// at the centre; only the BRDF × cos⁺ is averaged: the diffuse term by the clamped cosine's table
// (a cap straddling the horizon counts only its part above), the Phong lobe by its exponent's
// table around the mirror direction, times cos⁺ at the centre. With α = 0 the tables give back
// the centre's values, the `center` reflectivity. CELL_REFLECTIVITY_EXPONENTS lists the scene's
// Phong exponents (layer 1 + k), CELL_REFLECTIVITY_LAYERS their count.
#include "realtime/lighting/cell_reflectivity_shared.h"

layout(binding = kCellReflectivityUnit) uniform sampler2DArray u_cell_reflectivity;

float cellTable(int layer, float alpha, float cos_beta) {
  float beta = acos(clamp(cos_beta, -1.0, 1.0));
  return texture(u_cell_reflectivity,
                 vec3(cellReflectivityCoordinates(alpha, beta), float(layer))).r;
}

int cellExponentLayer(float exponent) {
#if CELL_REFLECTIVITY_LAYERS > 0
  const float exponents[] = CELL_REFLECTIVITY_EXPONENTS;
  for (int k = 0; k < CELL_REFLECTIVITY_LAYERS; ++k)
    if (exponents[k] == exponent) return 1 + k;
#endif
  return -1;
}

// False where the cell's centre is below the surface (as the centre's own light).
bool cellRadiance(int k, vec3 p, vec3 n, vec3 wo, vec3 diffuse, vec3 specular, float exponent,
                  bool phong, out vec3 radiance) {
  vec3 wi = -u_light_samples[k].axis.xyz;
  float cos_centre = dot(n, wi);
  if (cos_centre <= 0.0) return false;
  float alpha = u_light_samples[k].position.w;
  vec3 incident = u_light_samples[k].intensity.rgb * lightVisibility(k, p, n);
  // A directional light of the scene (no cell, α = 0) as the centre's own BRDF.
  if (alpha <= 0.0) {
    radiance = evaluateBrdf(diffuse, specular, exponent, phong, n, wo, wi) * cos_centre * incident;
    return true;
  }
  vec3 a = diffuse * kInvPi * cellTable(0, alpha, cos_centre);
  int layer = cellExponentLayer(exponent);
  if (phong) {
    // An exponent without a table (none: the technique makes one for each) would fall back to
    // the centre's lobe.
    vec3 r = 2.0 * dot(n, wo) * n - wo;
    float lobe = layer > 0 ? cellTable(layer, alpha, dot(r, wi))
                           : pow(max(dot(r, wi), 0.0), exponent);
    a += specular * ((exponent + 2.0) * 0.5 * kInvPi * lobe * cos_centre);
  }
  radiance = a * incident;
  return true;
}
