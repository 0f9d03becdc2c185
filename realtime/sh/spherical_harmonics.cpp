#include "realtime/sh/spherical_harmonics.h"

#include "realtime/sh/sh_basis.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gib::rt::sh {

namespace {

constexpr double kPi = std::numbers::pi;

// The area of the spherical projection of the cube-face rectangle from (0, 0) to (x, y) at
// distance 1: atan2(x·y, √(x² + y² + 1)) (a standard identity), used by inclusion–exclusion.
double cornerArea(double x, double y) {
  return std::atan2(x * y, std::sqrt(x * x + y * y + 1.0));
}

void checkBand(int band) {
  if (band < 0 || band > kShMaxBand)
    throw std::invalid_argument("spherical harmonics band must be 0 to 3");
}

// ∫ over the upper hemisphere of lobe(cosθ) · P_l(cosθ) dω · √((2l+1)/(4π)) · √(4π/(2l+1)), i.e.
// eq. 4's sqrt(4π/(2l+1))·ρ̂_l, by composite Simpson quadrature in cosθ (smooth integrands).
double zonalFactor(int l, const std::function<double(double)>& lobe) {
  auto legendre = [](int band, double x) {
    switch (band) {
      case 0:
        return 1.0;
      case 1:
        return x;
      case 2:
        return 0.5 * (3 * x * x - 1);
      default:
        return 0.5 * (5 * x * x * x - 3 * x);
    }
  };
  constexpr int kIntervals = 4096;  // even
  double sum = 0;
  for (int k = 0; k <= kIntervals; ++k) {
    const double x = double(k) / kIntervals;
    const double weight = (k == 0 || k == kIntervals) ? 1 : (k % 2 ? 4 : 2);
    sum += weight * lobe(x) * legendre(l, x);
  }
  // dω = 2π d(cosθ); Y_l0 = √((2l+1)/4π) P_l, and eq. 4 multiplies by √(4π/(2l+1)): those cancel.
  return 2 * kPi * sum / (3.0 * kIntervals);
}

}  // namespace

std::array<float, kShMaxCoefficients> evaluateBasis(const glm::vec3& d) {
  // The general basis (sh_basis.h) in double, rounded once: within float rounding of Sloan's
  // hand-expanded table that the GLSL basis keeps (spherical_harmonics.glsl).
  std::array<double, kShMaxCoefficients> y{};
  evaluateShBasis(glm::dvec3(d), kShMaxBand + 1, y);
  std::array<float, kShMaxCoefficients> result{};
  for (std::size_t i = 0; i < y.size(); ++i) result[i] = float(y[i]);
  return result;
}

glm::vec3 cubeTexelDirection(int face, int i, int j, int size) {
  // Texel centre in [−1, 1]², then OpenGL's table of cube-map face axes (spec §8.13).
  const float s = 2.0f * (float(i) + 0.5f) / float(size) - 1.0f;
  const float t = 2.0f * (float(j) + 0.5f) / float(size) - 1.0f;
  glm::vec3 d;
  switch (face) {
    case 0:
      d = {1, -t, -s};
      break;
    case 1:
      d = {-1, -t, s};
      break;
    case 2:
      d = {s, 1, t};
      break;
    case 3:
      d = {s, -1, -t};
      break;
    case 4:
      d = {s, -t, 1};
      break;
    default:
      d = {-s, -t, -1};
      break;
  }
  return glm::normalize(d);
}

double cubeTexelSolidAngle(int i, int j, int size) {
  const double x0 = 2.0 * i / size - 1, x1 = 2.0 * (i + 1) / size - 1;
  const double y0 = 2.0 * j / size - 1, y1 = 2.0 * (j + 1) / size - 1;
  return cornerArea(x1, y1) - cornerArea(x0, y1) - cornerArea(x1, y0) + cornerArea(x0, y0);
}

std::vector<float> cubeProjectionWeights(int size, int band) {
  checkBand(band);
  const int count = shCoefficientCount(band);
  std::vector<float> weights(std::size_t(6 * size * size * count));
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const auto y = evaluateBasis(cubeTexelDirection(face, i, j, size));
        const double area = cubeTexelSolidAngle(i, j, size);
        const std::size_t base = std::size_t(((face * size + j) * size + i) * count);
        for (int c = 0; c < count; ++c) weights[base + std::size_t(c)] = float(y[c] * area);
      }
  return weights;
}

std::vector<double> projectOnCube(const std::function<glm::dvec3(const glm::vec3&)>& radiance_rgb,
                                  int size, int band, int channel) {
  checkBand(band);
  const int count = shCoefficientCount(band);
  std::vector<double> coefficients(std::size_t(count), 0.0);
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const glm::vec3 d = cubeTexelDirection(face, i, j, size);
        const double value = radiance_rgb(d)[channel] * cubeTexelSolidAngle(i, j, size);
        const auto y = evaluateBasis(d);
        for (int c = 0; c < count; ++c) coefficients[std::size_t(c)] += value * y[c];
      }
  return coefficients;
}

std::array<float, kShMaxBand + 1> lambertBandFactors() {
  // Eq. 6 closed: ρ̂_l·√(4π/(2l+1)) = Â_l/π with Â = π, 2π/3, π/4, 0 (Ramamoorthi & Hanrahan
  // 2001). The OCR'd eq. 6 garbles the even-l case; this is its value.
  return {1.0f, 2.0f / 3.0f, 0.25f, 0.0f};
}

std::array<float, kShMaxBand + 1> zonalBandFactors(const std::function<double(double)>& lobe) {
  std::array<float, kShMaxBand + 1> factors{};
  for (int l = 0; l <= kShMaxBand; ++l) factors[std::size_t(l)] = float(zonalFactor(l, lobe));
  return factors;
}

std::array<float, kShMaxBand + 1> phongBandFactors(double exponent) {
  if (!(exponent >= 0)) throw std::invalid_argument("Phong exponent must be 0 or more");
  return zonalBandFactors(
      [exponent](double c) { return (exponent + 1) / (2 * kPi) * std::pow(c, exponent); });
}

}  // namespace gib::rt::sh
