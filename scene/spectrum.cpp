#include "scene/spectrum.h"

#include "scene/spectral_data.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gib::scene {

namespace {

void checkSpectrum(const SampledSpectrum& spectrum) {
  const auto& wavelengths = spectrum.wavelengths_nm;
  if (wavelengths.empty() || wavelengths.size() != spectrum.values.size())
    throw std::invalid_argument("a sampled spectrum needs as many values as wavelengths (>= 1)");
  for (std::size_t i = 0; i < wavelengths.size(); ++i) {
    if (!std::isfinite(wavelengths[i]) || !std::isfinite(spectrum.values[i]))
      throw std::invalid_argument("a sampled spectrum must be finite");
    if (i > 0 && !(wavelengths[i] > wavelengths[i - 1]))
      throw std::invalid_argument("a sampled spectrum's wavelengths must increase");
  }
}

float interpolate(const SampledSpectrum& spectrum, float wavelength_nm) {
  const auto& wavelengths = spectrum.wavelengths_nm;
  if (wavelength_nm < wavelengths.front() || wavelength_nm > wavelengths.back()) return 0.0f;
  // First sample strictly above λ; λ lies in [upper − 1, upper].
  const auto upper = std::upper_bound(wavelengths.begin(), wavelengths.end(), wavelength_nm);
  if (upper == wavelengths.end()) return spectrum.values.back();
  const std::size_t i = static_cast<std::size_t>(upper - wavelengths.begin());
  const float t = (wavelength_nm - wavelengths[i - 1]) / (wavelengths[i] - wavelengths[i - 1]);
  return spectrum.values[i - 1] + t * (spectrum.values[i] - spectrum.values[i - 1]);
}

// ∫ S(λ)·E(λ)·c̄(λ) dλ for c̄ = x̄, ȳ, z̄, with E the D65 table or 1 when `illuminant` is null.
// Trapezoid rule on the CIE 5 nm grid: the tables are only defined there, and the integrand is
// piecewise linear between grid points once S is resampled onto it, so a finer rule would only
// integrate our own interpolation of the tables more precisely, not the standard observer.
template <typename SpectrumFn>
glm::dvec3 integrateXyz(const SpectrumFn& spectrum, const CieTable* illuminant) {
  glm::dvec3 xyz(0.0);
  for (std::size_t i = 0; i < kCieSampleCount; ++i) {
    const bool end = i == 0 || i + 1 == kCieSampleCount;
    const double weight = end ? 0.5 * kCieWavelengthStepNm : kCieWavelengthStepNm;
    const double power = spectrum(static_cast<float>(cieWavelengthNm(i)));
    const double e = illuminant ? (*illuminant)[i] : 1.0;
    xyz += weight * power * e * glm::dvec3(kCie1931X[i], kCie1931Y[i], kCie1931Z[i]);
  }
  return xyz;
}

glm::dvec3 integrateXyz(const SampledSpectrum& spectrum, const CieTable* illuminant) {
  checkSpectrum(spectrum);
  return integrateXyz([&](float nm) { return interpolate(spectrum, nm); }, illuminant);
}

// ∫ E·ȳ dλ: the Y of a constant spectrum of 1, the normaliser of both conversions.
double integrateLuminance(const CieTable* illuminant) {
  return integrateXyz([](float) { return 1.0f; }, illuminant).y;
}

}  // namespace

float evaluateSpectrum(const SampledSpectrum& spectrum, float wavelength_nm) {
  checkSpectrum(spectrum);
  return interpolate(spectrum, wavelength_nm);
}

glm::vec3 xyzToLinearRec709(glm::vec3 xyz) {
  // The inverse of the matrix whose columns are the XYZ of the Rec.709 primaries scaled so that
  // RGB (1, 1, 1) is the D65 white XYZ (0.95047, 1, 1.08883), the white that the CIE 5 nm tables
  // integrate to (x, y = 0.31272, 0.32903); a perfect reflector under D65 therefore lands on
  // (1, 1, 1) to within 2e-4. Seven digits, as in pbrt and Lindbloom's tables.
  return {3.2404542f * xyz.x - 1.5371385f * xyz.y - 0.4985314f * xyz.z,
          -0.9692660f * xyz.x + 1.8760108f * xyz.y + 0.0415560f * xyz.z,
          0.0556434f * xyz.x - 0.2040259f * xyz.y + 1.0572252f * xyz.z};
}

Rgb reflectanceToRec709(const SampledSpectrum& reflectance) {
  const glm::dvec3 xyz = integrateXyz(reflectance, &kCieD65) / integrateLuminance(&kCieD65);
  return xyzToLinearRec709(glm::vec3(xyz));
}

Rgb emissionToRec709(const SampledSpectrum& radiance) {
  const glm::dvec3 xyz = integrateXyz(radiance, nullptr) / integrateLuminance(nullptr);
  return xyzToLinearRec709(glm::vec3(xyz));
}

}  // namespace gib::scene
