#include "realtime/sh/sh_projection.h"

#include "common/input_error.h"
#include "realtime/sh/sh_basis.h"
#include "realtime/sh/sh_rotation.h"

#include <glm/mat3x3.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace gib::rt::sh {

namespace {

constexpr double kPi = std::numbers::pi;

// Gauss–Legendre order and the widest θ interval it is applied to. Within a row the integrand
// P_l^m(cosθ)·sinθ is sin^{m+1}θ times a polynomial of degree l−m in cosθ: a trigonometric
// polynomial of degree at most l+1 ≤ 8, smooth everywhere. (In cosθ, as the brief's wording
// has it, odd m leave a factor √(1−cos²θ) that no polynomial rule integrates exactly and whose
// derivative is infinite at the poles, so the rule is taken in θ.) The n-point rule's error on an
// interval of width h is h^{2n+1}(n!)⁴/((2n+1)((2n)!)³)·max|f^{(2n)}| ≤ h·(kh)^{2n}·3e-20 for
// frequency k, n = 8: with h ≤ π/16 and k ≤ 8, kh ≤ π/2 and the relative error is below 1e-16,
// i.e. rounding. Rows wider than π/16 (maps under 16 rows high) are split into equal pieces.
constexpr int kGaussOrder = 8;
constexpr double kWidestPiece = kPi / 16;

struct GaussLegendre {
  std::array<double, kGaussOrder> nodes{}, weights{};  // on [−1, 1]
  GaussLegendre() {
    // Newton's method on P_n from Chebyshev-like starting points (Abramowitz & Stegun 25.4.29's
    // weights 2/((1−x²)P_n'(x)²)); converges to rounding in a few steps.
    for (int i = 0; i < kGaussOrder; ++i) {
      double x = std::cos(kPi * (i + 0.75) / (kGaussOrder + 0.5));
      double derivative = 0;
      for (int iteration = 0; iteration < 100; ++iteration) {
        double p0 = 1, p1 = x;
        for (int k = 2; k <= kGaussOrder; ++k) {
          const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        derivative = kGaussOrder * (x * p1 - p0) / (x * x - 1);
        const double step = p1 / derivative;
        x -= step;
        if (std::abs(step) < 1e-16) break;
      }
      nodes[std::size_t(i)] = x;
      weights[std::size_t(i)] = 2 / ((1 - x * x) * derivative * derivative);
    }
  }
};

const GaussLegendre& gaussLegendre() {
  static const GaussLegendre rule;
  return rule;
}

// The map's own frame with +y as polar axis: local (x', y', z') = (z, x, y) of a map direction,
// a cyclic permutation (a rotation), so φ' = atan2(x, z) = π/2 − φ for the map's azimuth φ. Its
// inverse, local → map, as glm columns.
const glm::dmat3 kLocalToMap(glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0));

// R_y(α)·d, the map turned into the world (scene/environment_map.h: +x turns towards −z).
glm::dmat3 mapToWorld(double rotation_deg) {
  const double a = glm::radians(rotation_deg);
  return glm::dmat3(glm::dvec3(std::cos(a), 0, -std::sin(a)), glm::dvec3(0, 1, 0),
                    glm::dvec3(std::sin(a), 0, std::cos(a)));
}

// ∫ N_l^m P_l^m(cosθ) sinθ dθ over row `row` for m ≥ 0, N the basis's constant (√2 K or K),
// index l·l + l + m: the basis at φ' = 0, d' = (sinθ, 0, cosθ), holds exactly N P_l^m(cosθ).
void rowIntegrals(int row, int height, int bands, std::span<double> out) {
  const GaussLegendre& rule = gaussLegendre();
  const double top = kPi * row / height, bottom = kPi * (row + 1) / height;
  const int pieces = int(std::ceil((bottom - top) / kWidestPiece - 1e-9));
  const double piece = (bottom - top) / pieces;
  std::array<double, shBasisCount(kShBasisMaxBands)> y{};
  std::fill(out.begin(), out.end(), 0.0);
  for (int p = 0; p < pieces; ++p)
    for (int q = 0; q < kGaussOrder; ++q) {
      const double theta = top + piece * (p + 0.5 * (1 + rule.nodes[std::size_t(q)]));
      const double weight = 0.5 * piece * rule.weights[std::size_t(q)] * std::sin(theta);
      evaluateShBasis(glm::dvec3(std::sin(theta), 0, std::cos(theta)), bands, y);
      for (int i = 0; i < shBasisCount(bands); ++i)
        out[std::size_t(i)] += weight * y[std::size_t(i)];
    }
}

}  // namespace

std::vector<glm::vec3> projectLatLong(const scene::EnvironmentMap& map, int bands) {
  checkShBands(bands);
  if (map.empty())
    throw InputError("projectLatLong: the environment map is empty; load one before projecting");
  const int width = map.width, height = map.height;
  const auto count = std::size_t(shBasisCount(bands));

  // Step 1: each column's ∫cos(mφ') dφ' and ∫sin(mφ') dφ' in closed form, from the midpoint
  // and half-width (2/m)·{cos, sin}(m·mid)·sin(m·half), well conditioned for thin columns.
  const double half = kPi / width;
  std::vector<double> column_cos(std::size_t(bands * width)), column_sin(column_cos.size());
  for (int m = 0; m < bands; ++m)
    for (int x = 0; x < width; ++x) {
      const double mid = kPi / 2 - 2 * kPi * (x + 0.5) / width;
      const auto k = std::size_t(m * width + x);
      column_cos[k] = m == 0 ? 2 * half : 2.0 / m * std::cos(m * mid) * std::sin(m * half);
      column_sin[k] = m == 0 ? 0.0 : 2.0 / m * std::sin(m * mid) * std::sin(m * half);
    }

  // Step 2: per row, the texels against each column integral, then times the row's θ
  // integrals into the local frame's coefficients.
  std::vector<glm::dvec3> local(count, glm::dvec3(0.0)), cos_sums(static_cast<std::size_t>(bands)),
      sin_sums(static_cast<std::size_t>(bands));
  std::vector<double> theta(count);
  for (int row = 0; row < height; ++row) {
    for (int m = 0; m < bands; ++m) {
      glm::dvec3 c(0.0), s(0.0);
      for (int x = 0; x < width; ++x) {
        const glm::dvec3 texel(map.texel(x, row));
        c += column_cos[std::size_t(m * width + x)] * texel;
        s += column_sin[std::size_t(m * width + x)] * texel;
      }
      cos_sums[std::size_t(m)] = c;
      sin_sums[std::size_t(m)] = s;
    }
    rowIntegrals(row, height, bands, theta);
    for (int l = 0; l < bands; ++l)
      for (int m = 0; m <= l; ++m) {
        const auto centre = std::size_t(l * l + l), M = std::size_t(m);
        local[centre + M] += theta[centre + M] * cos_sums[M];
        if (m > 0) local[centre - M] += theta[centre + M] * sin_sums[M];
      }
  }

  // Step 3: from the local frame to the world's: f_world(ω) = f_local((R_y·P⁻¹)⁻¹ω).
  std::vector<double> channel(count), turned(count);
  std::vector<glm::vec3> world(count);
  const ShRotation rotation(mapToWorld(map.rotation_deg) * kLocalToMap, bands);
  for (int c = 0; c < 3; ++c) {
    for (std::size_t i = 0; i < count; ++i) channel[i] = local[i][c] * double(map.intensity);
    rotation.apply(channel, turned);
    for (std::size_t i = 0; i < count; ++i) world[i][c] = float(turned[i]);
  }
  return world;
}

}  // namespace gib::rt::sh
