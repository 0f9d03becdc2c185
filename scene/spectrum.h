// Spectral data to linear Rec.709 RGB, the colour space of every radiance in GI Bench
// (docs/architecture.md, "Radiometry"). Used to turn the Cornell box's measured spectra into the
// RGB reflectances and emission of the built-in `cornell` scene.
#pragma once

#include "scene/scene.h"

#include <glm/vec3.hpp>

#include <vector>

namespace gib::scene {

// A spectrum sampled at increasing wavelengths, linear between samples and zero outside
// [wavelengths_nm.front(), wavelengths_nm.back()]. Both vectors have the same length (≥ 1).
struct SampledSpectrum {
  std::vector<float> wavelengths_nm;
  std::vector<float> values;
};

// The piecewise-linear value at `wavelength_nm` (zero outside the sampled range). Throws
// std::invalid_argument if the spectrum is malformed (sizes differ, empty, not increasing).
float evaluateSpectrum(const SampledSpectrum& spectrum, float wavelength_nm);

// CIE XYZ to linear Rec.709 (ITU-R BT.709 primaries, D65 white; the matrix of IEC 61966-2-1
// derived at seven digits): Y = 1 white maps to (1, 1, 1).
glm::vec3 xyzToLinearRec709(glm::vec3 xyz);

// The RGB reflectance of a surface with this spectral reflectance (values in [0, 1]) seen under
// D65: XYZ = ∫ R·D65·x̄ dλ / ∫ D65·ȳ dλ (so a perfect white reflector has Y = 1), then Rec.709.
// A flat reflectance ρ maps to (ρ, ρ, ρ) to within 2e-4: D65 is the white of Rec.709, so no
// chromatic adaptation is needed.
Rgb reflectanceToRec709(const SampledSpectrum& reflectance);

// The RGB radiance of an emitter with this spectral radiance (any unit; the Cornell light's
// published values are relative spectral radiance): XYZ = ∫ L·x̄ dλ / ∫ ȳ dλ, then Rec.709.
// The luminance of the result (Y) is the ȳ-weighted mean of L, so a relative spectrum keeps its
// scale: a flat L = 1 has Y = 1 (its colour is that of equal-energy white, slightly pink in
// Rec.709, since no chromatic adaptation is applied to light sources).
Rgb emissionToRec709(const SampledSpectrum& radiance);

}  // namespace gib::scene
