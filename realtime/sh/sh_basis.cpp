#include "realtime/sh/sh_basis.h"

#include "common/input_error.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gib::rt::sh {

namespace {

constexpr int kN = kShBasisMaxBands;

// The constants of the recurrences for m ≥ 0, l < kN, computed once in double.
struct LegendreTables {
  // (2m−1)!!: P_m^m(x) = (2m−1)!! (1−x²)^{m/2} without the Condon–Shortley (−1)^m. The book's
  // §8.3 prints (2l−1)!! here, a misprint: the start of column m depends on m alone (its own
  // code, after Green 2003, multiplies 1·3·…·(2m−1)).
  std::array<double, kN> start{};
  // P_l^m = x·a P_{l−1}^m − b P_{l−2}^m with a = (2l−1)/(l−m), b = (l+m−1)/(l−m) (book §8.3's
  // first rule), and P_{m+1}^m = x(2m+1) P_m^m (its third rule: a = 2m+1, b = 0).
  std::array<std::array<double, kN>, kN> a{}, b{};
  // √2 K_l^m for m > 0, K_l^0 for m = 0, with K_l^m = √((2l+1)/(4π)·(l−|m|)!/(l+|m|)!). The
  // book's K prints (k−|m|)! for (l−|m|)!, a misprint; its code uses factorial(l−m).
  std::array<std::array<double, kN>, kN> norm{};

  LegendreTables() {
    std::array<double, 2 * kN> factorial{};  // exact in double up to 2·7 = 14!
    factorial[0] = 1;
    for (int i = 1; i < 2 * kN; ++i) factorial[std::size_t(i)] = factorial[std::size_t(i - 1)] * i;
    double double_factorial = 1;  // (2m−1)!!, 1 for m = 0
    for (int m = 0; m < kN; ++m) {
      if (m > 0) double_factorial *= 2 * m - 1;
      start[std::size_t(m)] = double_factorial;
      for (int l = m; l < kN; ++l) {
        const auto L = std::size_t(l), M = std::size_t(m);
        if (l == m + 1) a[L][M] = 2 * m + 1;
        if (l > m + 1) {
          a[L][M] = double(2 * l - 1) / (l - m);
          b[L][M] = double(l + m - 1) / (l - m);
        }
        const double k =
            std::sqrt((2 * l + 1) / (4 * std::numbers::pi) * factorial[L - M] / factorial[L + M]);
        norm[L][M] = m == 0 ? k : std::numbers::sqrt2 * k;
      }
    }
  }
};

const LegendreTables& tables() {
  static const LegendreTables t;
  return t;
}

template <class T, class Vec>
void evaluate(const Vec& d, int bands, std::span<T> out) {
  checkShBands(bands);
  if (out.size() < std::size_t(shBasisCount(bands)))
    throw std::invalid_argument("evaluateShBasis: the output holds fewer than bands² values");
  const LegendreTables& t = tables();
  const T z = d.z;
  // Column m of the triangle of book §8.3: P̃_l^m = P_l^m / sin^m θ for l = m..bands−1, times the
  // azimuthal polynomials (c, s) = Re, Im (x + iy)^m = sin^m θ (cos mφ, sin mφ).
  T c = 1, s = 0;
  for (int m = 0; m < bands; ++m) {
    const auto M = std::size_t(m);
    T p_previous = 0;
    T p = T(t.start[M]);
    for (int l = m; l < bands; ++l) {
      const auto L = std::size_t(l);
      if (l > m) {
        const T next = z * T(t.a[L][M]) * p - T(t.b[L][M]) * p_previous;
        p_previous = p;
        p = next;
      }
      const T scaled = T(t.norm[L][M]) * p;
      const auto centre = std::size_t(l * l + l);
      if (m == 0) {
        out[centre] = scaled;
      } else {
        out[centre + M] = scaled * c;
        out[centre - M] = scaled * s;
      }
    }
    const T c_next = T(d.x) * c - T(d.y) * s;
    s = T(d.x) * s + T(d.y) * c;
    c = c_next;
  }
}

}  // namespace

void checkShBands(int bands) {
  if (bands < 1 || bands > kShBasisMaxBands)
    throw InputError(
        fmt::format("spherical-harmonic bands must be 1 to {} (n bands hold n² functions), not {}",
                    kShBasisMaxBands, bands));
}

void evaluateShBasis(const glm::vec3& d, int bands, std::span<float> out) {
  evaluate<float>(d, bands, out);
}

void evaluateShBasis(const glm::dvec3& d, int bands, std::span<double> out) {
  evaluate<double>(d, bands, out);
}

}  // namespace gib::rt::sh
