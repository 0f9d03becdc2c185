// An analytic clear sky as an environment map: A. J. Preetham, P. Shirley, B. Smits, "A Practical
// Analytic Model for Daylight", SIGGRAPH 1999 ("the paper" below).
//
// Sky: the paper's Perez distribution F(θ, γ) = (1 + A e^{B/cos θ})(1 + C e^{Dγ} + E cos²γ) for
// the luminance Y and the chromaticities x, y, each scaled by its zenith value:
// Y(θ, γ) = Y_z F(θ, γ) / F(0, θ_s). The coefficients A–E are linear in the turbidity T, the
// zenith luminance Y_z (kcd/m²) and chromaticities x_z, y_z are the paper's fits (Appendix A.2).
// Yxy → CIE XYZ → linear Rec.709 (scene/spectrum.h, D65 white, no chromatic adaptation, as for
// every emitter in GI Bench).
//
// Units: a texel value of 1 is a luminance of 1 kcd/m² (kSkyCandelasPerUnit), the unit of the
// paper's Y_z taken as it is; the zenith of a T = 3 sky with the sun 30° high is about 5. The
// map's `intensity` rescales it for a scene.
//
// Sun: the paper's sunlight (the transmittances of its appendix, after Iqbal 1983,
// "An Introduction to Solar Radiation"): the extraterrestrial solar spectral radiance attenuated
// by Rayleigh scattering, Ångström aerosol (α = 1.3, β = 0.04608 T − 0.04586), ozone (0.35 cm),
// mixed gases and water vapour (2 cm) along the relative optical air mass (Kasten 1966), in full
// spectral form (scene/preetham_sun.cpp), turned into luminance with 683 lm/W. A disc of angular
// radius 0.2667° (16′: the Sun subtends about 32′ at the mean Sun–Earth distance) far smaller than
// a texel, so its power goes into the one texel holding its centre: that texel's radiance grows
// by L_sun Ω_sun / Ω_texel, and ∫L dω grows by exactly L_sun Ω_sun.
//
// Ground (θ > 90°): a Lambertian plane of albedo 0.2 lit by the map's own sky rows and by the
// sun: L_ground = 0.2 (E_sky + L_sun Ω_sun cos θ_s) / π, constant over the lower hemisphere, so a
// scene without a floor still sees light from below as it would outdoors. Albedo 0.2 is the
// usual figure for grass and soil (the "0.2 ground reflectance" of daylighting practice).
//
// The map's height is even, so the horizon falls on a row boundary: the upper rows are sky, the
// lower rows ground, and none mixes the two.
#pragma once

#include "scene/environment_map.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace gib::scene {

struct SkyParameters {
  float sun_elevation_deg = 30;  // above the horizon, [0, 90]
  float sun_azimuth_deg = 0;     // the map's azimuth φ = atan2(z, x), from +x towards +z
  float turbidity = 3;           // [2, 10], the range the paper fitted
  int height = 128;              // map rows, even, [4, 4096]; width = 2 × height
};

// Throws gib::InputError with one line naming the problem and the fix.
void validateSkyParameters(const SkyParameters& parameters);

inline constexpr double kSkyCandelasPerUnit = 1000.0;  // texel 1 = 1 kcd/m² of luminance
inline constexpr double kSunAngularRadiusDeg = 0.2667;
inline constexpr double kSkyGroundAlbedo = 0.2;

// One row of the paper's Appendix A.2 distribution table at a turbidity.
struct PerezCoefficients {
  double a = 0, b = 0, c = 0, d = 0, e = 0;
};
struct SkyDistribution {
  PerezCoefficients luminance;  // Y
  PerezCoefficients x, y;       // chromaticity
};
SkyDistribution skyDistribution(double turbidity);

// F(θ, γ) for a view θ from the zenith (≤ π/2) and γ from the sun, radians.
double perezFunction(const PerezCoefficients& k, double theta, double gamma);

// The paper's zenith luminance (kcd/m²) and chromaticity for a sun θ_s from the zenith, radians.
double zenithLuminanceKcd(double turbidity, double sun_theta);
glm::dvec2 zenithChromaticity(double turbidity, double sun_theta);

// The sun's centre as a unit map direction.
glm::dvec3 sunDirection(const SkyParameters& parameters);
// The solid angle of the sun's disc, 2π(1 − cos 0.2667°), steradians.
double sunSolidAngle();
// The sun's radiance in linear Rec.709, in the map's units (kSkyCandelasPerUnit), for a sun θ_s
// from the zenith (radians, ≤ π/2).
Rgb sunRadiance(double turbidity, double sun_theta);

// The sky of one set of parameters, its coefficients evaluated once.
class PreethamSky {
 public:
  // Validates the parameters (gib::InputError).
  explicit PreethamSky(const SkyParameters& parameters);

  // (Y in kcd/m², x, y) of the sky in a unit map direction at or above the horizon (d.y ≥ 0).
  glm::dvec3 yxy(const glm::dvec3& direction) const;
  // The same as linear Rec.709 in the map's units, each channel clamped at 0 (a chromaticity
  // outside the Rec.709 gamut would give a negative channel, which no light may have).
  Rgb radiance(const glm::dvec3& direction) const;

  const SkyParameters& parameters() const { return parameters_; }
  const glm::dvec3& sunDirection() const { return sun_; }
  double sunTheta() const { return sun_theta_; }

 private:
  SkyParameters parameters_;
  glm::dvec3 sun_;
  double sun_theta_;
  SkyDistribution k_;
  glm::dvec3 zenith_yxy_;       // Y_z, x_z, y_z
  glm::dvec3 perez_at_zenith_;  // F(0, θ_s) of Y, x, y
};

// Whether the map holds the sun's disc. kOmitted leaves the sun's texel as the sky around it (for
// a caller that adds the sun as a light of its own, or to measure the sun's share); the ground
// stays lit by the sun either way.
enum class SunDisc { kIncluded, kOmitted };

// Each texel the sky's radiance at its centre direction (upper rows), the ground's (lower rows),
// the sun in its texel. Source: "preetham sky (sun elevation 30°, azimuth 0°, turbidity 3)".
// Validates the parameters (gib::InputError).
EnvironmentMap makePreethamSky(const SkyParameters& parameters, SunDisc sun = SunDisc::kIncluded);

}  // namespace gib::scene
