#include "scene/spectrum.h"

#include "scene/cornell_spectra.h"
#include "scene/spectral_data.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace gib::scene {
namespace {

// Published invariants of the CIE tables (CIE 015:2004): Σ ȳ·Δλ over 380–780 nm at 5 nm is
// 106.857; the D65 white point is (0.3127, 0.3290) to four decimals; x̄ peaks at 600 nm.
constexpr double kYbarIntegral = 106.857;
constexpr double kYbarIntegralTolerance = 0.05;
constexpr double kD65WhiteX = 0.3127;
constexpr double kD65WhiteY = 0.3290;
constexpr double kChromaticityTolerance = 3e-4;  // the tables give the white to four decimals
// The perfect white reflector's XYZ and the matrix's white differ in the fifth decimal.
constexpr float kFlatTolerance = 1e-3f;

SampledSpectrum flatSpectrum(float value) {
  return SampledSpectrum{{380.0f, 780.0f}, {value, value}};
}

std::size_t cieIndex(double wavelength_nm) {
  return static_cast<std::size_t>((wavelength_nm - kCieFirstWavelengthNm) / kCieWavelengthStepNm);
}

// ȳ at any wavelength, linear between the 5 nm samples; written here rather than taken from
// spectrum.cpp so that the luminance check below is independent of the code under test.
double ybarAt(double wavelength_nm) {
  if (wavelength_nm < kCieFirstWavelengthNm || wavelength_nm > cieWavelengthNm(kCieSampleCount - 1))
    return 0.0;
  const std::size_t i = std::min(cieIndex(wavelength_nm), kCieSampleCount - 2);
  const double t = (wavelength_nm - cieWavelengthNm(i)) / kCieWavelengthStepNm;
  return (1 - t) * kCie1931Y[i] + t * kCie1931Y[i + 1];
}

double spectrumAt(const SampledSpectrum& s, double wavelength_nm) {
  for (std::size_t i = 0; i + 1 < s.wavelengths_nm.size(); ++i) {
    if (wavelength_nm >= s.wavelengths_nm[i] && wavelength_nm <= s.wavelengths_nm[i + 1]) {
      const double t =
          (wavelength_nm - s.wavelengths_nm[i]) / (s.wavelengths_nm[i + 1] - s.wavelengths_nm[i]);
      return (1 - t) * s.values[i] + t * s.values[i + 1];
    }
  }
  return 0.0;
}

void printRgb(const char* what, const Rgb& c) {
  std::printf("[          ] %-14s Rec.709 (%.4f, %.4f, %.4f), luminance %.4f\n", what, c.r, c.g,
              c.b, luminance(c));
}

TEST(SpectralData, YbarIntegralMatchesCie) {
  double sum = 0;
  for (double y : kCie1931Y) sum += y * kCieWavelengthStepNm;
  EXPECT_NEAR(sum, kYbarIntegral, kYbarIntegralTolerance);
}

TEST(SpectralData, D65ChromaticityIsTheD65WhitePoint) {
  double x = 0, y = 0, z = 0;
  for (std::size_t i = 0; i < kCieSampleCount; ++i) {
    x += kCieD65[i] * kCie1931X[i];
    y += kCieD65[i] * kCie1931Y[i];
    z += kCieD65[i] * kCie1931Z[i];
  }
  EXPECT_NEAR(x / (x + y + z), kD65WhiteX, kChromaticityTolerance);
  EXPECT_NEAR(y / (x + y + z), kD65WhiteY, kChromaticityTolerance);
}

TEST(SpectralData, PeaksAreWherePublished) {
  const auto xbar_peak = std::max_element(kCie1931X.begin(), kCie1931X.end());
  EXPECT_DOUBLE_EQ(cieWavelengthNm(static_cast<std::size_t>(xbar_peak - kCie1931X.begin())), 600.0);
  EXPECT_NEAR(*xbar_peak, 1.0622, 1e-6);
  EXPECT_DOUBLE_EQ(kCie1931Y[cieIndex(555.0)], 1.0);
  EXPECT_DOUBLE_EQ(kCieD65[cieIndex(560.0)], 100.0);
}

TEST(Spectrum, EvaluatesPiecewiseLinearAndZeroOutside) {
  const SampledSpectrum s{{400.0f, 500.0f, 600.0f}, {0.0f, 1.0f, 3.0f}};
  EXPECT_FLOAT_EQ(evaluateSpectrum(s, 450.0f), 0.5f);
  EXPECT_FLOAT_EQ(evaluateSpectrum(s, 550.0f), 2.0f);
  EXPECT_FLOAT_EQ(evaluateSpectrum(s, 600.0f), 3.0f);
  EXPECT_FLOAT_EQ(evaluateSpectrum(s, 399.0f), 0.0f);
  EXPECT_FLOAT_EQ(evaluateSpectrum(s, 601.0f), 0.0f);
}

TEST(Spectrum, RejectsMalformedSpectra) {
  EXPECT_THROW(reflectanceToRec709(SampledSpectrum{}), std::invalid_argument);
  EXPECT_THROW(reflectanceToRec709(SampledSpectrum{{400.0f, 500.0f}, {1.0f}}),
               std::invalid_argument);
  EXPECT_THROW(emissionToRec709(SampledSpectrum{{500.0f, 400.0f}, {1.0f, 1.0f}}),
               std::invalid_argument);
}

TEST(Spectrum, D65WhiteMapsToRec709White) {
  const Rgb white = xyzToLinearRec709({0.95047f, 1.0f, 1.08883f});
  EXPECT_NEAR(white.r, 1.0f, 1e-4f);
  EXPECT_NEAR(white.g, 1.0f, 1e-4f);
  EXPECT_NEAR(white.b, 1.0f, 1e-4f);
}

TEST(Spectrum, FlatReflectanceIsGrey) {
  for (float rho : {1.0f, 0.5f, 0.0f}) {
    const Rgb c = reflectanceToRec709(flatSpectrum(rho));
    EXPECT_NEAR(c.r, rho, kFlatTolerance) << rho;
    EXPECT_NEAR(c.g, rho, kFlatTolerance) << rho;
    EXPECT_NEAR(c.b, rho, kFlatTolerance) << rho;
  }
}

TEST(Spectrum, FlatEmissionHasItsValueAsLuminance) {
  const Rgb c = emissionToRec709(flatSpectrum(2.0f));
  EXPECT_NEAR(luminance(c), 2.0f, 2e-3f);
}

TEST(CornellSpectra, HaveThePublishedSamples) {
  const SampledSpectrum white = cornellWhite();
  ASSERT_EQ(white.values.size(), 76u);
  EXPECT_FLOAT_EQ(white.wavelengths_nm.front(), 400.0f);
  EXPECT_FLOAT_EQ(white.wavelengths_nm.back(), 700.0f);
  EXPECT_FLOAT_EQ(white.values[0], 0.343f);
  EXPECT_FLOAT_EQ(white.values[3], 0.624f);
  EXPECT_FLOAT_EQ(white.values[75], 0.737f);
  EXPECT_FLOAT_EQ(cornellRed().values[2], 0.048f);
  EXPECT_FLOAT_EQ(cornellRed().values[75], 0.642f);
  EXPECT_FLOAT_EQ(cornellGreen().values[2], 0.098f);
  EXPECT_FLOAT_EQ(cornellGreen().values[32], 0.481f);  // 528 nm, the green peak
  EXPECT_FLOAT_EQ(cornellLight().values[2], 15.6f);
}

TEST(CornellSpectra, RedIsRed) {
  const Rgb red = reflectanceToRec709(cornellRed());
  printRgb("cornell red", red);
  EXPECT_GT(red.r, 3 * red.g);
  EXPECT_GT(red.r, 3 * red.b);
}

TEST(CornellSpectra, GreenIsGreen) {
  const Rgb green = reflectanceToRec709(cornellGreen());
  printRgb("cornell green", green);
  EXPECT_GT(green.g, green.r);
  EXPECT_GT(green.g, green.b);
}

TEST(CornellSpectra, WhiteIsNearlyNeutral) {
  const Rgb white = reflectanceToRec709(cornellWhite());
  printRgb("cornell white", white);
  const float mean = (white.r + white.g + white.b) / 3;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(white[c], mean, 0.1f * mean) << "channel " << c;
  EXPECT_GT(luminance(white), 0.6f);
  EXPECT_LT(luminance(white), 0.8f);
}

TEST(CornellSpectra, LightIsWarmWithTheSpectrumsMeanLuminance) {
  const SampledSpectrum light = cornellLight();
  const Rgb radiance = emissionToRec709(light);
  printRgb("cornell light", radiance);
  EXPECT_GT(radiance.r, radiance.g);
  EXPECT_GT(radiance.g, radiance.b);
  EXPECT_GT(radiance.b, 0.0f);

  // ȳ-weighted mean of the light's spectrum by a 1 nm sum.
  double weighted = 0, weights = 0;
  for (int nm = 380; nm <= 780; ++nm) {
    weighted += spectrumAt(light, nm) * ybarAt(nm);
    weights += ybarAt(nm);
  }
  const double expected = weighted / weights;
  std::printf("[          ] ybar-weighted mean of the light spectrum: %.4f\n", expected);
  EXPECT_NEAR(luminance(radiance), expected, 0.01 * expected);
}

}  // namespace
}  // namespace gib::scene
