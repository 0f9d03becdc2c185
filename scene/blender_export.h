// A GI Bench scene as a Blender Python script that rebuilds it in an empty file and renders it
// with Cycles, so the reference can be checked against an independent path tracer
// (scripts/cross-check-cycles.sh). The script is the scene's data followed by a fixed builder
// (scene/blender_scene.py); every conversion of units and conventions is made here, so the
// builder only copies numbers into Blender.
#pragma once

#include "scene/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace gib::scene {

struct BlenderExportSettings {
  int width = 0;
  int height = 0;
  int spp = 0;
  std::uint64_t seed = 0;  // Cycles takes 0 to 2^31 − 1
};

struct BlenderExport {
  std::string script;  // run as `blender -b --factory-startup --python FILE -- OUT.exr`
  // What Cycles cannot reproduce exactly (Phong lobes, spot fall-off other than cos θ, media,
  // caustics of point and directional lamps), one line each.
  std::vector<std::string> warnings;
};

// Throws gib::InputError for settings Cycles cannot take (a size or sample count below 1, a seed
// beyond Cycles' range).
BlenderExport exportBlenderScript(const Scene& scene, const BlenderExportSettings& settings);

// Blender's spot and point lamps are given as power P in watts; Cycles emits P/(4π) W/sr from
// them (intern/cycles/scene/light.cpp: eval_fac = 1/(4π) for a lamp of radius 0), so an
// intensity of I W/sr is 4π·I watts. A spot lamp multiplies this by cos θ inside its cone, as a
// GI Bench spot light of fall-off exponent 1 does (measured: docs/cycles-cross-check.md).
double blenderLampWatts(double intensity_w_per_sr);

// Cycles' Beckmann roughness r whose distribution has α = r² equal to the Beckmann α that
// matches a Phong exponent n (Walter et al. 2007, "Microfacet models for refraction through
// rough surfaces", eq. 34: α = √(2 / (n + 2))).
double phongToBeckmannRoughness(double exponent);

// Cycles' Volume Absorption node of colour C and density ρ absorbs with the coefficient
// σ = ρ·(1 − C) per channel and per world unit (intern/cycles/kernel/svm/closure.h,
// svm_node_closure_volume: the weight of an absorption closure is (1 − C)·ρ), so light crossing a
// distance d keeps exp(−ρ(1 − C)·d). The exported meshes are placed without scaling (a scene unit
// is a world unit), so GI Bench's exp(−a·d) is matched by ρ = max(a) and C = 1 − a/ρ: then
// ρ(1 − C) = a, exact up to the rounding of C to a float (an error below 2⁻²⁴·ρ in σ; none in the
// largest channel, whose C is 0). `absorption` must have a positive channel.
struct CyclesAbsorption {
  Rgb color{0.0f};
  float density = 0.0f;
};
CyclesAbsorption cyclesAbsorption(const Rgb& absorption);

}  // namespace gib::scene
