// Distribution functions the statistical tests need (chi-square goodness of fit, Z-tests):
// written out here because the standard library has no incomplete gamma function.
#pragma once

namespace gib::metrics {

// Regularised lower incomplete gamma P(a, x) = γ(a, x) / Γ(a), for a > 0, x ≥ 0.
double regularizedGammaP(double a, double x);
// Q(a, x) = 1 − P(a, x), computed directly for accuracy in the tail.
double regularizedGammaQ(double a, double x);

// P(X ≥ x) for X ~ χ²(dof): the p-value of a chi-square statistic.
double chiSquareSurvival(double x, double dof);

// Standard normal CDF Φ(z) and its inverse (Acklam's rational approximation refined by one
// Halley step; relative error below 1e-12 over (0, 1)).
double normalCdf(double z);
double normalQuantile(double p);

// Šidák correction: the per-test significance that keeps the family-wise rate at `alpha` over
// `tests` independent tests, 1 − (1 − α)^(1/m).
double sidakSignificance(double alpha, double tests);

// Regularised incomplete beta I_x(a, b), for a, b > 0 and 0 ≤ x ≤ 1.
double regularizedBetaI(double a, double b, double x);

// Student's t distribution with `dof` > 0 degrees of freedom: P(T ≤ t), and its inverse (to
// 1e-12 in p).
double studentTCdf(double t, double dof);
double studentTQuantile(double p, double dof);

}  // namespace gib::metrics
