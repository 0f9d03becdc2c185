#include "scene/preetham_sky.h"

#include "common/input_error.h"
#include "common/parallel_for.h"
#include "scene/spectrum.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace gib::scene {

namespace {

constexpr double kPi = std::numbers::pi;

constexpr double kMinTurbidity = 2.0;
constexpr double kMaxTurbidity = 10.0;
constexpr int kMinHeight = 4;
constexpr int kMaxHeight = 4096;

double radians(double degrees) {
  return degrees * kPi / 180.0;
}

// Linear in T: one coefficient of the paper's Appendix A.2 table, (slope, intercept).
double linear(double turbidity, double slope, double intercept) {
  return slope * turbidity + intercept;
}

// [T², T, 1] · M · [θ³, θ², θ, 1]ᵀ: the paper's zenith chromaticity fits (Appendix A.2).
double zenithPolynomial(const double (&m)[3][4], double turbidity, double theta) {
  const double t[3] = {turbidity * turbidity, turbidity, 1.0};
  const double th[4] = {theta * theta * theta, theta * theta, theta, 1.0};
  double sum = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) sum += t[i] * m[i][j] * th[j];
  return sum;
}

glm::vec3 yxyToXyz(const glm::dvec3& yxy) {
  const double big_y = yxy.x, x = yxy.y, y = yxy.z;
  return glm::vec3(glm::dvec3(x / y * big_y, big_y, (1.0 - x - y) / y * big_y));
}

// Ω of the texels of row `row` (of `height`): 2π/width · (cos θ₀ − cos θ₁).
double texelSolidAngle(int row, int height) {
  const double width = 2.0 * height;
  return 2 * kPi / width * (std::cos(kPi * row / height) - std::cos(kPi * (row + 1) / height));
}

}  // namespace

void validateSkyParameters(const SkyParameters& p) {
  if (!(p.sun_elevation_deg >= 0 && p.sun_elevation_deg <= 90))
    throw InputError(fmt::format(
        "sun elevation {}° is outside [0, 90]; the Preetham model is for a sun above the "
        "horizon: give an elevation from 0 to 90 degrees",
        p.sun_elevation_deg));
  if (!std::isfinite(p.sun_azimuth_deg))
    throw InputError("sun azimuth must be a finite angle in degrees (0 looks along +x)");
  if (!(p.turbidity >= kMinTurbidity && p.turbidity <= kMaxTurbidity))
    throw InputError(fmt::format(
        "turbidity {} is outside [{}, {}], the range the Preetham model was fitted over; give a "
        "turbidity from {} (very clear) to {} (hazy)",
        p.turbidity, kMinTurbidity, kMaxTurbidity, kMinTurbidity, kMaxTurbidity));
  if (p.height < kMinHeight || p.height > kMaxHeight || p.height % 2 != 0)
    throw InputError(fmt::format(
        "sky height {} must be even and in [{}, {}] (even, so the horizon lies between rows); "
        "give e.g. 128",
        p.height, kMinHeight, kMaxHeight));
}

SkyDistribution skyDistribution(double t) {
  // Preetham et al. 1999, Appendix A.2: the distribution coefficients of Y, x and y, each
  // (slope, intercept) in the turbidity T.
  SkyDistribution k;
  k.luminance = {linear(t, 0.1787, -1.4630), linear(t, -0.3554, 0.4275), linear(t, -0.0227, 5.3251),
                 linear(t, 0.1206, -2.5771), linear(t, -0.0670, 0.3703)};
  k.x = {linear(t, -0.0193, -0.2592), linear(t, -0.0665, 0.0008), linear(t, -0.0004, 0.2125),
         linear(t, -0.0641, -0.8989), linear(t, -0.0033, 0.0452)};
  k.y = {linear(t, -0.0167, -0.2608), linear(t, -0.0950, 0.0092), linear(t, -0.0079, 0.2102),
         linear(t, -0.0441, -1.6537), linear(t, -0.0109, 0.0529)};
  return k;
}

double perezFunction(const PerezCoefficients& k, double theta, double gamma) {
  // At the horizon cos θ → 0 and B < 0 over the fitted range, so e^{B/cos θ} → 0: the
  // gradation term tends to 1 rather than overflowing.
  const double cos_theta = std::cos(theta);
  const double gradation = cos_theta > 0 ? 1.0 + k.a * std::exp(k.b / cos_theta) : 1.0;
  const double cos_gamma = std::cos(gamma);
  return gradation * (1.0 + k.c * std::exp(k.d * gamma) + k.e * cos_gamma * cos_gamma);
}

double zenithLuminanceKcd(double t, double sun_theta) {
  // Preetham et al. 1999, Appendix A.2: Y_z in kcd/m².
  const double chi = (4.0 / 9.0 - t / 120.0) * (kPi - 2.0 * sun_theta);
  return (4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192;
}

glm::dvec2 zenithChromaticity(double t, double sun_theta) {
  // Preetham et al. 1999, Appendix A.2: the 3 × 4 matrices of x_z and y_z.
  static constexpr double kX[3][4] = {{0.00166, -0.00375, 0.00209, 0.0},
                                      {-0.02903, 0.06377, -0.03202, 0.00394},
                                      {0.11693, -0.21196, 0.06052, 0.25886}};
  static constexpr double kY[3][4] = {{0.00275, -0.00610, 0.00317, 0.0},
                                      {-0.04214, 0.08970, -0.04153, 0.00516},
                                      {0.15346, -0.26756, 0.06670, 0.26688}};
  return {zenithPolynomial(kX, t, sun_theta), zenithPolynomial(kY, t, sun_theta)};
}

glm::dvec3 sunDirection(const SkyParameters& p) {
  const double elevation = radians(p.sun_elevation_deg);
  const double azimuth = radians(p.sun_azimuth_deg);
  return {std::cos(elevation) * std::cos(azimuth), std::sin(elevation),
          std::cos(elevation) * std::sin(azimuth)};
}

double sunSolidAngle() {
  return 2 * kPi * (1.0 - std::cos(radians(kSunAngularRadiusDeg)));
}

PreethamSky::PreethamSky(const SkyParameters& parameters) : parameters_(parameters) {
  validateSkyParameters(parameters_);
  sun_ = scene::sunDirection(parameters_);
  sun_theta_ = radians(90.0 - double(parameters_.sun_elevation_deg));
  const double t = parameters_.turbidity;
  k_ = skyDistribution(t);
  const glm::dvec2 xy = zenithChromaticity(t, sun_theta_);
  zenith_yxy_ = {zenithLuminanceKcd(t, sun_theta_), xy.x, xy.y};
  // At the zenith θ = 0 and γ = θ_s.
  perez_at_zenith_ = {perezFunction(k_.luminance, 0.0, sun_theta_),
                      perezFunction(k_.x, 0.0, sun_theta_), perezFunction(k_.y, 0.0, sun_theta_)};
}

glm::dvec3 PreethamSky::yxy(const glm::dvec3& d) const {
  const double theta = std::acos(std::clamp(d.y, 0.0, 1.0));
  const double gamma = std::acos(std::clamp(glm::dot(d, sun_), -1.0, 1.0));
  const glm::dvec3 f = {perezFunction(k_.luminance, theta, gamma),
                        perezFunction(k_.x, theta, gamma), perezFunction(k_.y, theta, gamma)};
  return zenith_yxy_ * f / perez_at_zenith_;
}

Rgb PreethamSky::radiance(const glm::dvec3& d) const {
  glm::vec3 xyz = yxyToXyz(yxy(d));
  // Y is in kcd/m², the map's unit when kSkyCandelasPerUnit is 1000.
  xyz *= float(1000.0 / kSkyCandelasPerUnit);
  return glm::max(xyzToLinearRec709(xyz), Rgb(0.0f));
}

EnvironmentMap makePreethamSky(const SkyParameters& parameters, SunDisc sun) {
  const PreethamSky sky(parameters);
  const int height = parameters.height;
  const int width = 2 * height;
  const int sky_rows = height / 2;
  std::vector<float> texels(3 * std::size_t(width) * std::size_t(height));
  auto at = [&](int x, int y) { return texels.data() + 3 * (std::size_t(y) * width + x); };

  // Step 1: the sky rows, each texel at its centre direction.
  parallelFor(std::size_t(sky_rows), 0, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t row = begin; row < end; ++row) {
      const double theta = kPi * (double(row) + 0.5) / height;
      for (int x = 0; x < width; ++x) {
        const double phi = 2 * kPi * (x + 0.5) / width;
        const glm::dvec3 d = {std::sin(theta) * std::cos(phi), std::cos(theta),
                              std::sin(theta) * std::sin(phi)};
        const Rgb l = sky.radiance(d);
        std::copy(&l[0], &l[0] + 3, at(x, int(row)));
      }
    }
  });

  // Step 2: the ground, lit by the sky rows exactly as the map holds them (each row's
  // ∫cos θ dω = π/width · (cos²θ₀ − cos²θ₁)) and by the sun's disc.
  const Rgb l_sun = sunRadiance(parameters.turbidity, sky.sunTheta());
  glm::dvec3 irradiance = glm::dvec3(l_sun) * sunSolidAngle() * std::cos(sky.sunTheta());
  for (int y = 0; y < sky_rows; ++y) {
    const double c0 = std::cos(kPi * y / height), c1 = std::cos(kPi * (y + 1) / height);
    const double projected = kPi / width * (c0 * c0 - c1 * c1);
    for (int x = 0; x < width; ++x)
      irradiance += projected * glm::dvec3(Rgb(at(x, y)[0], at(x, y)[1], at(x, y)[2]));
  }
  const Rgb ground = Rgb(kSkyGroundAlbedo / kPi * irradiance);
  for (int y = sky_rows; y < height; ++y)
    for (int x = 0; x < width; ++x) std::copy(&ground[0], &ground[0] + 3, at(x, y));

  // Step 3: the sun's power into the texel that holds its centre (the sky side of the horizon
  // for a sun exactly on it).
  if (sun == SunDisc::kIncluded) {
    const glm::vec2 uv = latLongCoordinates(glm::vec3(sky.sunDirection()));
    const int x = std::min(int(uv.x * float(width)), width - 1);
    const int y = std::min(int(uv.y * float(height)), sky_rows - 1);
    const Rgb added = l_sun * float(sunSolidAngle() / texelSolidAngle(y, height));
    for (int c = 0; c < 3; ++c) at(x, y)[c] += added[c];
  }

  return makeEnvironmentMap(
      width, height, std::move(texels),
      fmt::format("preetham sky (sun elevation {}°, azimuth {}°, turbidity {})",
                  parameters.sun_elevation_deg, parameters.sun_azimuth_deg, parameters.turbidity));
}

}  // namespace gib::scene
