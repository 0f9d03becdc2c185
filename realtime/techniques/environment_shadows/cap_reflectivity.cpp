#include "realtime/techniques/environment_shadows/cap_reflectivity.h"

#include "realtime/lighting/cell_reflectivity_shared.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gib::rt {

namespace {

constexpr double kPi = std::numbers::pi;
// Midpoint steps over the cap's range of γ (at most 2α wide): 256 resolve a cos¹⁰⁰ lobe (about
// 0.12 rad wide at half height) with ten points even in a cap that is the whole sphere.
constexpr int kSteps = 256;

// The fraction of the circle at angle γ from the lobe axis inside the cap.
double insideFraction(double gamma, double cos_alpha, double beta) {
  const double across = std::sin(gamma) * std::sin(beta);
  const double along = std::cos(gamma) * std::cos(beta);
  // On the axis (γ or β at 0 or π) the circle is all in or all out.
  if (across < 1e-12) return along >= cos_alpha ? 1.0 : 0.0;
  return std::acos(std::clamp((cos_alpha - along) / across, -1.0, 1.0)) / kPi;
}

}  // namespace

double capMeanCosinePower(double s, double alpha, double beta) {
  const double centre = std::pow(std::max(0.0, std::cos(beta)), s);
  if (alpha <= 0) return centre;
  const double cos_alpha = std::cos(alpha);
  const double lo = std::max(0.0, beta - alpha), hi = std::min(kPi, beta + alpha);
  // The cap's solid angle by the same quadrature, so that s = 0 gives exactly 1 and the
  // quadrature's error partly cancels in the ratio.
  double weighted = 0, area = 0;
  const double step = (hi - lo) / kSteps;
  for (int k = 0; k < kSteps; ++k) {
    const double gamma = lo + (k + 0.5) * step;
    const double measure = std::sin(gamma) * insideFraction(gamma, cos_alpha, beta);
    area += measure;
    const double c = std::cos(gamma);
    if (c > 0) weighted += measure * std::pow(c, s);
  }
  return area > 0 ? weighted / area : centre;
}

std::vector<float> capReflectivityTable(double s) {
  const int n = gpu::kCellReflectivitySize;
  const auto angle = [n](int k) {
    const double root = double(k) / double(n - 1);
    return kPi * root * root;
  };
  std::vector<float> table(std::size_t(n) * std::size_t(n));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      table[std::size_t(j) * std::size_t(n) + std::size_t(i)] =
          float(capMeanCosinePower(s, angle(i), angle(j)));
  return table;
}

}  // namespace gib::rt
