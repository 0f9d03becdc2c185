// The participating medium's particles on the GPU (book §9.2), read by their C++ and their GLSL:
// the particle buffer, the storage bindings and texture units the particle passes share, and the
// closed forms both techniques evaluate (scene/medium.h defines the density: σt(p) = τ·(1 − d/r)
// inside each sphere, overlapping particles adding).
#pragma once
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>

namespace gib::rt::gpu {
using glm::dot;
using std::asinh;
using std::exp;
using std::sqrt;
#endif

struct GpuParticle {
  vec4 centre_radius;  // xyz: centre (world), w: radius
  vec4 density;        // x: τ, the extinction at the centre (per scene unit); yzw unused
};

// Storage bindings shared by the particle passes (realtime/particles/); a technique's own buffers
// take the slots a pass of its own does not bind (illumination_network_shared.h says which).
const int kParticlesBinding = kTechniqueFirstStorageBinding + 0;       // GpuParticle[N]
const int kParticleOrderBinding = kTechniqueFirstStorageBinding + 1;   // uint[N], back to front
const int kParticleSourceBinding = kTechniqueFirstStorageBinding + 2;  // vec4[N] towards the eye
const int kTransmittanceBinding =
    kTechniqueFirstStorageBinding + 3;  // float[N × M] to M directions
const int kSphereDirectionsBinding = kTechniqueFirstStorageBinding + 4;  // vec4[D]
// The illumination network's incoming radiance, vec4[N × D], read by the view shading: it takes
// the order's slot, which that pass does not bind.
const int kIncomingRadianceBinding = kParticleOrderBinding;

const int kPhaseTableUnit = kTechniqueFirstUnit + 0;  // sampler1D: P(cos θ) over [−1, 1]
const int kPhaseTableSize = 1024;

// Directional lights the passes read as uniform arrays (the book measures 1, 2 and 4).
const int kMaxParticleLights = 8;

// How a billboard's opacity is computed from its ray segment (book §9.3.1, §9.3.1.1).
const int kOpacityLinear = 0;       // the linear fall-off integrated exactly (closed form)
const int kOpacityGouraud = 1;      // the book's 1 − exp(−τ (1 − d/r) Δs)
const int kOpacityHomogeneous = 2;  // constant density τ: 1 − exp(−τ Δs)

const int kParticleGroupSize = 64;

const float kFourPi = 12.566370614359172f;

// ∫ √(d² + s²) ds, up to a constant: the distance from the centre integrated along a line that
// passes at distance d from it (s measured from the line's point closest to the centre).
GIB_SHARED_FUNCTION float distanceIntegral(float s, float d) {
  float h = sqrt(d * d + s * s);
  return 0.5f * (s * h + (d > 0.0f ? d * d * asinh(s / d) : 0.0f));
}

// Optical depth of one particle (radius r, centre density tau) along the part s ∈ [s0, s1] of a
// line passing at distance d from its centre, s measured from the line's point closest to the
// centre: ∫ τ (1 − √(d² + s²)/r) ds over the segment clipped to the sphere.
GIB_SHARED_FUNCTION float chordOpticalDepth(float tau, float r, float d, float s0, float s1) {
  if (d >= r) return 0.0f;
  float w = sqrt(r * r - d * d);
  float a = s0 > -w ? s0 : -w;
  float b = s1 < w ? s1 : w;
  if (b <= a) return 0.0f;
  float depth = tau * ((b - a) - (distanceIntegral(b, d) - distanceIntegral(a, d)) / r);
  return depth > 0.0f ? depth : 0.0f;
}

// Optical depth of particle q along origin + t·omega (omega unit) for t in [0, distance]: the
// part of its chord on that segment (volume shadows, surfaces lit through the medium).
GIB_SHARED_FUNCTION float particleSegmentDepth(GpuParticle q, vec3 origin, vec3 omega,
                                               float distance) {
  float r = q.centre_radius.w;
  vec3 v = vec3(q.centre_radius) - origin;
  float t = dot(v, omega);
  if (t < -r || t > distance + r) return 0.0f;
  float d2 = dot(v, v) - t * t;
  if (d2 >= r * r) return 0.0f;
  return chordOpticalDepth(q.density.x, r, sqrt(d2 > 0.0f ? d2 : 0.0f), -t, distance - t);
}

// Henyey–Greenstein p(θ) = (1 − g²) / (4π (1 + g² − 2g cos θ)^{3/2}), θ between the propagation
// directions before and after scattering; the reference's phase function.
GIB_SHARED_FUNCTION float henyeyGreensteinPhase(float cos_theta, float g) {
  float denominator = 1.0f + g * g - 2.0f * g * cos_theta;
  return (1.0f - g * g) / (kFourPi * denominator * sqrt(denominator));
}

// The phase table's texture coordinate of cos θ: texel i holds cos θ = −1 + 2i/(size − 1).
GIB_SHARED_FUNCTION float phaseTableCoordinate(float cos_theta) {
  float x = 0.5f * (cos_theta + 1.0f);
  return (x * float(kPhaseTableSize - 1) + 0.5f) / float(kPhaseTableSize);
}

#ifdef __cplusplus
static_assert(sizeof(GpuParticle) == 32, "std430 struct GpuParticle: two vec4");
static_assert(kSphereDirectionsBinding <
              kTechniqueFirstStorageBinding + kTechniqueStorageBindingCount);
}  // namespace gib::rt::gpu
#endif
