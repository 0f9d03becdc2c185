// The sun's radiance of Preetham, Shirley & Smits 1999 (scene/preetham_sky.h): the
// extraterrestrial solar spectral radiance times the transmittances of the clear atmosphere along
// the relative optical air mass, after Iqbal 1983, "An Introduction to Solar Radiation", whose
// tables the paper's sunlight model uses.
#include "scene/preetham_sky.h"

#include "scene/spectral_data.h"
#include "scene/spectrum.h"

#include <cmath>
#include <numbers>
#include <vector>

namespace gib::scene {

namespace {

// Extraterrestrial solar spectral radiance, 380–750 nm every 10 nm, in 100 W/(m²·sr·nm) (so
// 287.1 at 500 nm is 28 710 W/(m²·sr·nm)); the paper's sunlight table (Iqbal 1983). Check: times
// the disc's 6.8e-5 sr and integrated against 683·ȳ it gives 128 klx, the solar illuminance
// constant (127.5 klx in the older literature, 133.8 klx in Darula, Kittler & Gueymard 2005).
// Zero beyond 750 nm, where the table ends (ȳ < 1.2e-4 there: 0.001 % of Y).
const SampledSpectrum kSolarRadiance = {
    {380, 390, 400, 410, 420, 430, 440, 450, 460, 470, 480, 490, 500, 510, 520, 530, 540, 550, 560,
     570, 580, 590, 600, 610, 620, 630, 640, 650, 660, 670, 680, 690, 700, 710, 720, 730, 740, 750},
    {165.5, 162.3, 211.2, 258.8, 258.2, 242.3, 267.6, 296.6, 305.4, 300.6, 306.6, 288.3, 287.1,
     278.2, 271.0, 272.3, 263.6, 255.0, 250.6, 253.1, 253.5, 251.3, 246.3, 241.7, 236.8, 232.1,
     228.2, 223.4, 219.7, 215.3, 211.0, 207.3, 202.4, 198.7, 194.3, 190.7, 186.3, 182.6}};
constexpr double kSolarRadianceUnit = 100.0;  // W/(m²·sr·nm) per table unit

// Ozone absorption coefficient k_o, cm⁻¹ (Iqbal 1983, p. 127). The table skips 355–445 nm, where
// ozone hardly absorbs; read linearly between its neighbours (0 and 0.003) there.
const SampledSpectrum kOzoneAbsorption = {
    {300, 305, 310, 315, 320, 325, 330, 335, 340, 345, 350, 355, 445, 450, 455, 460,
     465, 470, 475, 480, 485, 490, 495, 500, 505, 510, 515, 520, 525, 530, 535, 540,
     545, 550, 555, 560, 565, 570, 575, 580, 585, 590, 595, 600, 605, 610, 620, 630,
     640, 650, 660, 670, 680, 690, 700, 710, 720, 730, 740, 750, 760, 770, 780, 790},
    {10.0,  4.8,   2.7,   1.35,  0.8,   0.38,  0.16,  0.075, 0.04,  0.019, 0.007, 0.0,   0.003,
     0.003, 0.004, 0.006, 0.008, 0.009, 0.012, 0.014, 0.017, 0.021, 0.025, 0.03,  0.035, 0.04,
     0.045, 0.048, 0.057, 0.063, 0.07,  0.075, 0.08,  0.085, 0.095, 0.103, 0.110, 0.12,  0.122,
     0.12,  0.118, 0.115, 0.12,  0.125, 0.130, 0.12,  0.105, 0.09,  0.079, 0.067, 0.057, 0.048,
     0.036, 0.028, 0.023, 0.018, 0.014, 0.011, 0.010, 0.009, 0.007, 0.004, 0.0,   0.0}};

// Mixed-gas (O₂ A band) absorption coefficient k_g, cm⁻¹ (Iqbal 1983, p. 130).
const SampledSpectrum kGasAbsorption = {{759, 760, 770, 771}, {0.0, 3.0, 0.210, 0.0}};

// Water-vapour absorption coefficient k_wa, cm⁻¹ (Iqbal 1983, p. 130).
const SampledSpectrum kWaterAbsorption = {
    {689, 690, 700, 710, 720, 730, 740, 750, 760, 770, 780, 790, 800},
    {0.0, 0.016, 0.024, 0.0125, 1.0, 0.87, 0.061, 0.001, 1e-5, 1e-5, 6e-4, 0.0175, 0.036}};

constexpr double kOzoneCm = 0.35;            // ozone layer thickness, cm (NTP)
constexpr double kWaterVapourCm = 2.0;       // precipitable water vapour, cm
constexpr double kAngstromAlpha = 1.3;       // ratio of small to large aerosol particles
constexpr double kLuminousEfficacy = 683.0;  // lm/W at 555 nm

// The product of the five transmittances at one wavelength for air mass m.
double transmittance(double nm, double m, double turbidity) {
  const double um = nm / 1000.0;
  const double beta = 0.04608365822050 * turbidity - 0.04586025928522;
  const double rayleigh = std::exp(-m * 0.008735 * std::pow(um, -4.08));
  const double aerosol = std::exp(-m * beta * std::pow(um, -kAngstromAlpha));
  const double ozone = std::exp(-m * evaluateSpectrum(kOzoneAbsorption, float(nm)) * kOzoneCm);
  const double kg = evaluateSpectrum(kGasAbsorption, float(nm));
  const double gas = std::exp(-1.41 * kg * m / std::pow(1.0 + 118.93 * kg * m, 0.45));
  const double kwa = evaluateSpectrum(kWaterAbsorption, float(nm));
  const double water = std::exp(-0.2385 * kwa * kWaterVapourCm * m /
                                std::pow(1.0 + 20.07 * kwa * kWaterVapourCm * m, 0.45));
  return rayleigh * aerosol * ozone * gas * water;
}

// ∫ȳ dλ by the trapezoid rule on the CIE grid, the rule emissionToRec709 integrates with.
double integralOfYBar() {
  double sum = 0;
  for (std::size_t i = 0; i < kCieSampleCount; ++i)
    sum += (i == 0 || i + 1 == kCieSampleCount ? 0.5 : 1.0) * kCieWavelengthStepNm * kCie1931Y[i];
  return sum;
}

}  // namespace

Rgb sunRadiance(double turbidity, double sun_theta) {
  // Relative optical air mass (Kasten 1966), θ_s in degrees inside the correction term; finite
  // (≈ 36) with the sun on the horizon.
  const double theta_deg = sun_theta * 180.0 / std::numbers::pi;
  const double m = 1.0 / (std::cos(sun_theta) + 0.15 * std::pow(93.885 - theta_deg, -1.253));

  // The attenuated spectral radiance on the CIE grid, W/(m²·sr·nm).
  SampledSpectrum attenuated;
  for (std::size_t i = 0; i < kCieSampleCount; ++i) {
    const double nm = cieWavelengthNm(i);
    const double s0 = kSolarRadianceUnit * evaluateSpectrum(kSolarRadiance, float(nm));
    attenuated.wavelengths_nm.push_back(float(nm));
    attenuated.values.push_back(float(s0 * transmittance(nm, m, turbidity)));
  }
  // emissionToRec709 gives the ȳ-weighted mean radiance; times ∫ȳ dλ and 683 lm/W it is the
  // luminance in cd/m², then in the map's units.
  const double scale = integralOfYBar() * kLuminousEfficacy / kSkyCandelasPerUnit;
  return emissionToRec709(attenuated) * float(scale);
}

}  // namespace gib::scene
