// What an obscurance is (book Ch. 10, eq. 10.1–10.5): the definition shared by the reference,
// which estimates it exactly with Embree (a reference of this quantity instead of radiance), and
// the obscurances technique, which approximates it with global ray bundles; and the ambient light
// of eq. 10.3 and 10.5, computed from the scene. docs/rendering.md, "Obscurances".
#pragma once

#include "scene/obscurance_shared.h"
#include "scene/scene.h"

#include <string>
#include <string_view>

namespace gib::scene {

enum class ObscuranceFalloff {
  kSqrt = kObscuranceFalloffSqrt,              // the book's ρ(d) = √(d/d_max)
  kAmbientOcclusion = kObscuranceFalloffStep,  // a step at d_max
};

enum class ObscuranceMode {
  kScalar,    // eq. 10.2: W ∈ [0, 1], grey
  kSpectral,  // eq. 10.4: weighted by the albedo seen, per channel (colour bleeding)
};

// The obscurance W(x) of eq. 10.2 (scalar) or 10.4 (spectral) with fall-off ρ up to d_max.
struct ObscuranceDefinition {
  ObscuranceFalloff falloff = ObscuranceFalloff::kSqrt;
  ObscuranceMode mode = ObscuranceMode::kScalar;
  // d_max as a fraction of the diagonal of the scene's bounding box (maxDistance gives it in scene
  // units), so that one value means the same neighbourhood in every scene.
  float d_max_fraction = kDefaultObscuranceDistanceFraction;

  static constexpr float kDefaultObscuranceDistanceFraction = 0.25f;
  bool operator==(const ObscuranceDefinition&) const = default;
};

// "sqrt" | "ambient_occlusion", "scalar" | "spectral": as parameters, flags and metadata name them.
std::string_view obscuranceFalloffName(ObscuranceFalloff falloff);
std::string_view obscuranceModeName(ObscuranceMode mode);
// Throw gib::InputError naming the choices for any other name.
ObscuranceFalloff parseObscuranceFalloff(std::string_view name);
ObscuranceMode parseObscuranceMode(std::string_view name);
// Throws gib::InputError unless 0 < fraction ≤ 100 (finite), naming the fix.
void validateObscuranceDistanceFraction(float fraction);

// "obscurance(sqrt, scalar, d_max=0.25)": what a reference of it is of, in results and metadata.
std::string describeObscurance(const ObscuranceDefinition& definition);

// The diagonal of the bounding box of the scene's meshes (0 without geometry).
float sceneDiagonal(const Scene& scene);
// d_max in scene units: d_max_fraction × sceneDiagonal.
float maxDistance(const Scene& scene, const ObscuranceDefinition& definition);

// A material's albedo a as the obscurances see it: the diffuse reflectance ρd (π times the
// diffuse BRDF, book eq. 1.12); zero for mirrors and glass, which have no diffuse part.
Rgb obscuranceAlbedo(const Material& material);

// The scene's averages over its surfaces, weighted by area (book §10.1): ã = Σ Aᵢaᵢ / S and the
// emitted power per unit area Σ AᵢLᵢᵉ / S, where a point or spot light counts as the power Φ/π
// of a Lambertian emitter of the same power (Φ = π·A·Lᵉ). Directional light and the sky are not
// emitted inside the scene and do not count (the book's ambient light is for closed scenes).
struct SceneAverages {
  double area = 0;             // S
  Rgb albedo{0.0f};            // ã (= ā of eq. 10.5)
  Rgb emitted_per_area{0.0f};  // Σ AᵢLᵢᵉ / S
};
SceneAverages sceneAverages(const Scene& scene);

// Lᵃ: eq. 10.3, ã/(1 − ã)·L̃ᵉ, for the scalar method; eq. 10.5, L̃ᵉ/(1 − ā), for the spectral one
// (its W carries the albedo of the first reflection). Per channel; a channel with ã ≥ 1 (an
// energy-conserving scene never has one) is clamped to ã = 0.999.
Rgb ambientLight(const SceneAverages& averages, ObscuranceMode mode);

}  // namespace gib::scene
