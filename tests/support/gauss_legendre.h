// Gauss–Legendre nodes and weights on [−1, 1] for the spherical-harmonic tests' own quadratures
// (the n-point rule is exact for polynomials of degree ≤ 2n − 1), by Newton's method on P_n from
// the usual cosine starting points, with weights 2/((1 − x²) P_n'(x)²) (Abramowitz & Stegun
// 25.4.29). Written apart from the library's rule so that the tests do not check it by itself.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

namespace gib::test {

struct QuadratureRule {
  std::vector<double> x, w;
};

inline QuadratureRule gaussLegendre(int n) {
  QuadratureRule rule;
  for (int i = 0; i < n; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int step = 0; step < 100; ++step) {  // converged after a handful; more costs nothing
      double p0 = 1, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1);
      x -= p1 / dp;
    }
    rule.x.push_back(x);
    rule.w.push_back(2 / ((1 - x * x) * dp * dp));
  }
  return rule;
}

}  // namespace gib::test
