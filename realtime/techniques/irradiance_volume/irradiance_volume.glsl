// The irradiance volume's lookup (Nijasure et al. 2005, §3.3, §4.4 and §6): the spherical-harmonic
// coefficients of incident radiance at the probes, interpolated trilinearly to a surface point,
// and the reflected radiance through eq. 4's zonal transfer factors. Coefficients live in a
// buffer and are interpolated here rather than by 3D-texture hardware, because §6's
// indirect shadows weight the eight probes by their visibility, which hardware filtering cannot.
#include "realtime/sh/spherical_harmonics.glsl"
#include "realtime/techniques/irradiance_volume/irradiance_volume_shared.h"

// The coefficient buffer the projection writes, read as a buffer texture: texel
// probeCoefficientIndex(probe, i) holds the rgb of coefficient i (gathered across a SIMD row on
// llvmpipe, where a storage buffer is read lane by lane).
layout(binding = kProbeCoefficientsUnit) uniform samplerBuffer u_coefficients;
layout(std430, binding = kPhongFactorsBinding) readonly buffer PhongFactors {
  vec4 phong_factors[];  // per material: eq. 4's band factors of its Phong lobe, bands 0..3
};
layout(binding = kProbePositionUnit) uniform sampler2D u_probe_position;  // w: distance to probe

uniform int u_grid_n;
uniform vec3 u_grid_origin;
uniform vec3 u_grid_cell;
// SH_COEFFICIENT_COUNT (4, 9 or 16), the coefficients in use, is compiled in: loops over them then
// unroll and the coefficient arrays live in registers (llvmpipe keeps an array indexed by a
// uniform-bounded loop in memory, addressed lane by lane).
#ifndef SH_COEFFICIENT_COUNT
#error "define SH_COEFFICIENT_COUNT, the spherical-harmonic coefficients in use"
#endif
uniform vec4 u_lambert_factors;   // eq. 6 per band, for unit albedo
uniform bool u_indirect_shadows;
uniform int u_face;     // cube face size
uniform int u_tiles_x;  // atlas tiles per row

int probeIndex(ivec3 g) {
  return (g.z * u_grid_n + g.y) * u_grid_n + g.x;
}

vec3 probePosition(ivec3 g) {
  return u_grid_origin + (vec3(g) + 0.5) * u_grid_cell;
}

// The distance the probe's cube map sees along unit direction d (sh::cubeTexelDirection's
// inverse: the major axis picks the face, the other two give the texel).
float probeDistance(int probe, vec3 d) {
  vec3 a = abs(d);
  int face;
  vec2 st;
  if (a.x >= a.y && a.x >= a.z) {
    face = d.x > 0.0 ? 0 : 1;
    st = vec2(d.x > 0.0 ? -d.z : d.z, -d.y) / a.x;
  } else if (a.y >= a.z) {
    face = d.y > 0.0 ? 2 : 3;
    st = vec2(d.x, d.y > 0.0 ? d.z : -d.z) / a.y;
  } else {
    face = d.z > 0.0 ? 4 : 5;
    st = vec2(d.z > 0.0 ? d.x : -d.x, -d.y) / a.z;
  }
  ivec2 texel = clamp(ivec2((st * 0.5 + 0.5) * float(u_face)), ivec2(0), ivec2(u_face - 1));
  ivec2 origin = tileOrigin(probeTile(probe, face), u_tiles_x, u_face);
  return texelFetch(u_probe_position, origin + texel, 0).w;
}

// The incident radiance coefficients at p: trilinear weights over the cell's eight probes (clamped
// at the grid's outer half cells), each multiplied, with indirect shadows, by whether the probe's
// cube map sees p (its recorded distance towards p is not shorter than p's, up to a tolerance of
// a tenth of a cell), and renormalised. Without a visible probe the plain weights stand.
void interpolateCoefficients(vec3 p, out vec3 L[kShMaxCoefficients]) {
  vec3 g = clamp((p - u_grid_origin) / u_grid_cell - 0.5, vec3(0.0), vec3(float(u_grid_n - 1)));
  ivec3 base = min(ivec3(floor(g)), ivec3(u_grid_n - 2));
  if (u_grid_n == 1) base = ivec3(0);
  vec3 f = g - vec3(base);
  float weights[8];
  int probes[8];
  float total = 0.0, visible_total = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    ivec3 offset = ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    vec3 w3 = mix(1.0 - f, f, vec3(offset));
    probes[corner] = probeIndex(min(base + offset, ivec3(u_grid_n - 1)));
    weights[corner] = w3.x * w3.y * w3.z;
    total += weights[corner];
  }
  if (u_indirect_shadows) {
    float tolerance = 0.1 * min(u_grid_cell.x, min(u_grid_cell.y, u_grid_cell.z));
    float shadowed[8];
    for (int corner = 0; corner < 8; ++corner) {
      ivec3 offset = ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
      vec3 to_p = p - probePosition(min(base + offset, ivec3(u_grid_n - 1)));
      float distance = length(to_p);
      bool sees = distance < 1e-6 || probeDistance(probes[corner], to_p / distance) + tolerance >= distance;
      shadowed[corner] = sees ? weights[corner] : 0.0;
      visible_total += shadowed[corner];
    }
    if (visible_total > 0.0) {
      for (int corner = 0; corner < 8; ++corner) weights[corner] = shadowed[corner];
      total = visible_total;
    }
  }
  for (int i = 0; i < kShMaxCoefficients; ++i) L[i] = vec3(0.0);
  for (int corner = 0; corner < 8; ++corner) {
    float w = weights[corner] / total;
    if (w == 0.0) continue;
    for (int i = 0; i < SH_COEFFICIENT_COUNT; ++i)
      L[i] += w * texelFetch(u_coefficients, probeCoefficientIndex(probes[corner], i)).rgb;
  }
}

// Eq. 4: Σ_l factor_l Σ_m L_lm Y_lm(axis).
vec3 zonalTransfer(vec3 L[kShMaxCoefficients], vec3 axis, vec4 factors) {
  float y[kShMaxCoefficients];
  shBasis(axis, y);
  vec3 result = vec3(0.0);
  for (int i = 0; i < SH_COEFFICIENT_COUNT; ++i) result += factors[shBand(i)] * y[i] * L[i];
  return max(result, vec3(0.0));  // a truncated expansion can ring below zero
}
