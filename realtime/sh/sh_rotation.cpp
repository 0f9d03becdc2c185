#include "realtime/sh/sh_rotation.h"

#include "realtime/sh/sh_basis.h"

#include <glm/vec3.hpp>

#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace gib::rt::sh {

namespace {

// The offset of band l's matrix: Σ_{k<l} (2k+1)² = l(2l−1)(2l+1)/3.
std::size_t bandOffset(int l) {
  return std::size_t(l * (2 * l - 1) * (2 * l + 1) / 3);
}

void checkSize(std::size_t in, std::size_t out, int bands) {
  const auto count = std::size_t(shBasisCount(bands));
  if (in < count || out < count)
    throw std::invalid_argument("ShRotation::apply: a coefficient vector holds fewer than bands²");
}

// Band l of Ivanic & Ruedenberg's recurrence (1996, Tables 1 and 2, with the 1998 corrections
// to V and W): D^l_mn = u_mn U_mn + v_mn V_mn + w_mn W_mn, each term a product of band 1's matrix
// and band l−1's (`previous`).
void recurBand(int l, const double r1[3][3], const double* previous, double* out) {
  const int previous_size = 2 * l - 1, size = 2 * l + 1;
  auto r = [&](int i, int j) { return r1[i + 1][j + 1]; };
  auto before = [&](int a, int b) { return previous[(a + l - 1) * previous_size + (b + l - 1)]; };
  // Their function P^l_{i,a,b}: band 1's row i against band l−1's row a, the columns ±l folded.
  auto p = [&](int i, int a, int b) {
    if (b == l) return r(i, 1) * before(a, l - 1) - r(i, -1) * before(a, -l + 1);
    if (b == -l) return r(i, 1) * before(a, -l + 1) + r(i, -1) * before(a, l - 1);
    return r(i, 0) * before(a, b);
  };
  for (int m = -l; m <= l; ++m) {
    const int am = std::abs(m);
    const double d0 = m == 0 ? 1.0 : 0.0;
    for (int n = -l; n <= l; ++n) {
      const double denominator =
          std::abs(n) < l ? double((l + n) * (l - n)) : double(2 * l * (2 * l - 1));
      const double u = std::sqrt((l + m) * (l - m) / denominator);
      const double v =
          0.5 * std::sqrt((1 + d0) * (l + am - 1) * (l + am) / denominator) * (1 - 2 * d0);
      const double w = -0.5 * std::sqrt((l - am - 1) * (l - am) / denominator) * (1 - d0);
      double value = 0;
      if (u != 0) value += u * p(0, m, n);
      if (v != 0) {
        double big_v;
        if (m == 0) {
          big_v = p(1, 1, n) + p(-1, -1, n);
        } else if (m > 0) {
          const double d1 = m == 1 ? 1.0 : 0.0;
          big_v = p(1, m - 1, n) * std::sqrt(1 + d1) - p(-1, -m + 1, n) * (1 - d1);
        } else {
          const double d1 = m == -1 ? 1.0 : 0.0;
          big_v = p(1, m + 1, n) * (1 - d1) + p(-1, -m - 1, n) * std::sqrt(1 + d1);
        }
        value += v * big_v;
      }
      if (w != 0) {  // zero for |m| ≥ l−1, where W would reach outside band l−1
        const double big_w =
            m > 0 ? p(1, m + 1, n) + p(-1, -m - 1, n) : p(1, m - 1, n) - p(-1, -m + 1, n);
        value += w * big_w;
      }
      out[(m + l) * size + (n + l)] = value;
    }
  }
}

// out_m = Σ_n D_mn in_n (or Σ_n D_nm in_n, transposed) over one band, accumulated in double.
template <class In, class Acc>
void multiplyBand(const double* matrix, int size, const In* in, In* out, bool transpose) {
  for (int m = 0; m < size; ++m) {
    Acc sum(0);
    for (int n = 0; n < size; ++n)
      sum += (transpose ? matrix[n * size + m] : matrix[m * size + n]) * Acc(in[n]);
    out[m] = In(sum);
  }
}

template <class In, class Acc>
void multiplyAll(const ShRotation& rotation, const In* in, In* out, bool transpose) {
  for (int l = 0; l < rotation.bands(); ++l)
    multiplyBand<In, Acc>(rotation.bandMatrix(l).data(), 2 * l + 1, in + l * l, out + l * l,
                          transpose);
}

template <class T>
void turnAboutZ(T* c, int bands, float angle) {
  for (int l = 1; l < bands; ++l) {
    T* centre = c + l * l + l;
    for (int m = 1; m <= l; ++m) {
      const auto cosine = float(std::cos(double(m) * double(angle)));
      const auto sine = float(std::sin(double(m) * double(angle)));
      const T cos_term = centre[m], sin_term = centre[-m];
      centre[m] = cos_term * cosine - sin_term * sine;
      centre[-m] = cos_term * sine + sin_term * cosine;
    }
  }
}

// D(Q) for the quarter turn Q = R_x(−90°) (+y → −z, +z → +y), every band rotateAboutY serves.
const ShRotation& quarterTurnAboutX() {
  static const ShRotation q(
      glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0)), kShBasisMaxBands);
  return q;
}

template <class T, class Acc>
void turnAboutY(std::span<T> c, int bands, float angle) {
  checkShBands(bands);
  checkSize(c.size(), c.size(), bands);
  const ShRotation& q = quarterTurnAboutX();
  std::vector<T> t(std::size_t(shBasisCount(bands)));
  // D(Q)ᵀ takes f's frame to the one where +y is the polar axis, turn there, D(Q) back.
  for (int l = 0; l < bands; ++l)
    multiplyBand<T, Acc>(q.bandMatrix(l).data(), 2 * l + 1, c.data() + l * l, t.data() + l * l,
                         true);
  turnAboutZ(t.data(), bands, angle);
  for (int l = 0; l < bands; ++l)
    multiplyBand<T, Acc>(q.bandMatrix(l).data(), 2 * l + 1, t.data() + l * l, c.data() + l * l,
                         false);
}

}  // namespace

ShRotation::ShRotation(const glm::dmat3& rotation, int bands)
    : bands_(bands), matrices_(bandOffset(bands)) {
  checkShBands(bands);
  matrices_[0] = 1;
  if (bands == 1) return;
  // Band 1's basis is (y, z, x) times one constant, so D¹ is R with rows and columns in that
  // order: g(ω) = a·R⁻¹ω = (R a)·ω for f(ω) = a·ω. glm indexes [column][row].
  constexpr int kAxis[3] = {1, 2, 0};  // m = −1, 0, 1 → y, z, x
  double r1[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r1[i][j] = rotation[kAxis[j]][kAxis[i]];
  double* band1 = matrices_.data() + bandOffset(1);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) band1[i * 3 + j] = r1[i][j];
  for (int l = 2; l < bands; ++l)
    recurBand(l, r1, matrices_.data() + bandOffset(l - 1), matrices_.data() + bandOffset(l));
}

ShRotation::ShRotation(const glm::mat3& rotation, int bands)
    : ShRotation(glm::dmat3(rotation), bands) {}

std::span<const double> ShRotation::bandMatrix(int l) const {
  if (l < 0 || l >= bands_) throw std::invalid_argument("ShRotation::bandMatrix: no such band");
  return {matrices_.data() + bandOffset(l), std::size_t((2 * l + 1) * (2 * l + 1))};
}

void ShRotation::apply(std::span<const float> in, std::span<float> out) const {
  checkSize(in.size(), out.size(), bands_);
  multiplyAll<float, double>(*this, in.data(), out.data(), false);
}

void ShRotation::apply(std::span<const double> in, std::span<double> out) const {
  checkSize(in.size(), out.size(), bands_);
  multiplyAll<double, double>(*this, in.data(), out.data(), false);
}

void ShRotation::apply(std::span<const glm::vec3> in, std::span<glm::vec3> out) const {
  checkSize(in.size(), out.size(), bands_);
  multiplyAll<glm::vec3, glm::dvec3>(*this, in.data(), out.data(), false);
}

std::vector<glm::vec3> ShRotation::apply(std::span<const glm::vec3> in) const {
  std::vector<glm::vec3> out(std::size_t(shBasisCount(bands_)));
  apply(in, out);
  return out;
}

void rotateAboutZ(std::span<float> coefficients, int bands, float angle) {
  checkShBands(bands);
  checkSize(coefficients.size(), coefficients.size(), bands);
  turnAboutZ(coefficients.data(), bands, angle);
}

void rotateAboutZ(std::span<glm::vec3> coefficients, int bands, float angle) {
  checkShBands(bands);
  checkSize(coefficients.size(), coefficients.size(), bands);
  turnAboutZ(coefficients.data(), bands, angle);
}

void rotateAboutY(std::span<float> coefficients, int bands, float angle) {
  turnAboutY<float, double>(coefficients, bands, angle);
}

void rotateAboutY(std::span<glm::vec3> coefficients, int bands, float angle) {
  turnAboutY<glm::vec3, glm::dvec3>(coefficients, bands, angle);
}

}  // namespace gib::rt::sh
