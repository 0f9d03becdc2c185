// Colorimetric tables that spectrum.cpp integrates against: the CIE 1931 2° standard observer and
// the CIE standard illuminant D65, both tabulated every 5 nm from 380 to 780 nm (81 samples).
// Sources and cross-checks are named beside the numbers in spectral_data.cpp.
#pragma once

#include <array>
#include <cstddef>

namespace gib::scene {

inline constexpr double kCieFirstWavelengthNm = 380.0;
inline constexpr double kCieWavelengthStepNm = 5.0;
inline constexpr std::size_t kCieSampleCount = 81;  // 380, 385, ..., 780 nm

using CieTable = std::array<double, kCieSampleCount>;

// Colour-matching functions x̄(λ), ȳ(λ), z̄(λ) of the CIE 1931 2° standard observer;
// ȳ is the photopic luminous efficiency V(λ), 1 at 555 nm.
extern const CieTable kCie1931X;
extern const CieTable kCie1931Y;
extern const CieTable kCie1931Z;

// Relative spectral power of CIE standard illuminant D65, 100 at 560 nm.
extern const CieTable kCieD65;

// Wavelength of sample i of the tables above.
constexpr double cieWavelengthNm(std::size_t i) {
  return kCieFirstWavelengthNm + kCieWavelengthStepNm * static_cast<double>(i);
}

}  // namespace gib::scene
