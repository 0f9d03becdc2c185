#include "realtime/techniques/irradiance_cache/ward_hemisphere.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gib::rt {

namespace {
constexpr float kPi = std::numbers::pi_v<float>;
}

WardStrata wardStrata(int rays) {
  WardStrata s;
  s.theta = std::max(1, int(std::lround(std::sqrt(double(rays) / std::numbers::pi))));
  s.phi = std::max(1, int(std::lround(double(rays) / s.theta)));
  return s;
}

glm::vec3 wardDirection(const glm::vec3& t, const glm::vec3& b, const glm::vec3& n, int j, int k,
                        const WardStrata& strata, const glm::vec2& u) {
  const float sin2 = (float(j) + u.x) / float(strata.theta);
  const float sin_theta = std::sqrt(sin2), cos_theta = std::sqrt(std::max(0.0f, 1.0f - sin2));
  const float phi = 2.0f * kPi * (float(k) + u.y) / float(strata.phi);
  return sin_theta * std::cos(phi) * t + sin_theta * std::sin(phi) * b + cos_theta * n;
}

gpu::IrradianceRecord wardRecord(const glm::vec3& p, const glm::vec3& n, const WardStrata& strata,
                                 std::span<const HemisphereSample> samples) {
  const int m = strata.theta, nphi = strata.phi;
  const glm::vec3 t = gpu::basisTangent(n), b = gpu::basisBitangent(n);
  auto at = [&](int j, int k) -> const HemisphereSample& {
    return samples[std::size_t(j) * std::size_t(nphi) + std::size_t((k + nphi) % nphi)];
  };
  // Each stratum has the same cos θ dω = π/(MN).
  const float cell = kPi / float(m * nphi);
  const float half_sector = kPi / float(nphi);
  const float sector_sinc = std::sin(half_sector) / half_sector;
  glm::vec3 e(0.0f), rotation[3] = {}, translation[3] = {};
  double inverse_distances = 0;
  for (int j = 0; j < m; ++j) {
    // Ward's rotation gradient weighs a stratum by tan θ. Taken at the stratum's centre, as
    // Ward & Heckbert do, it misses that tan θ grows without bound towards the horizon (the last
    // ring's mean is about twice its centre value; a normal tilted 3° then moved E 7% less than
    // predicted): the mean over the ring, uniform in u = sin²θ, is exact for a radiance constant
    // over each stratum. ∫ √(u/(1 − u)) du = asin √u − √(u(1 − u)).
    auto tan_integral = [](double u) { return std::asin(std::sqrt(u)) - std::sqrt(u * (1 - u)); };
    const float tan_mean =
        float((tan_integral(double(j + 1) / m) - tan_integral(double(j) / m)) * double(m));
    // The ring boundary below ring j (between j − 1 and j) at sin²θ = j/M.
    const float sin_lo = std::sqrt(float(j) / float(m));
    const float cos_lo = std::sqrt(std::max(0.0f, 1.0f - sin_lo * sin_lo));
    const float sin_hi = std::sqrt(float(j + 1) / float(m));
    for (int k = 0; k < nphi; ++k) {
      const HemisphereSample& s = at(j, k);
      e += s.radiance;
      inverse_distances += std::isfinite(s.distance) ? 1.0 / double(s.distance) : 0.0;
      const float phi_centre = 2.0f * kPi * (float(k) + 0.5f) / float(nphi);
      // n × ω over its length sin θ is the unit vector at φ + π/2; its mean over the sector is
      // the centre's times sinc(δφ/2).
      const glm::vec3 v_centre =
          sector_sinc * (-std::sin(phi_centre) * t + std::cos(phi_centre) * b);
      for (int c = 0; c < 3; ++c) rotation[c] += (cell * tan_mean * s.radiance[c]) * v_centre;
      // Ring boundary: length sin θ·2π/N, cosine-weighted and moved along u_k by cos θ per unit
      // of translation: sin θ cos² θ · 2π/N (Ward & Heckbert's first term).
      if (j > 0) {
        const HemisphereSample& below = at(j - 1, k);
        const glm::vec3 u_k = std::cos(phi_centre) * t + std::sin(phi_centre) * b;
        const float weight = sin_lo * cos_lo * cos_lo * (2.0f * kPi / float(nphi)) /
                             std::min(below.distance, s.distance);
        for (int c = 0; c < 3; ++c)
          translation[c] += (weight * (s.radiance[c] - below.radiance[c])) * u_k;
      }
      // Sector boundary at φ = 2πk/N: ∫ cos θ dθ over the ring, moved along v (φ + π/2).
      const HemisphereSample& before = at(j, k - 1);
      const float phi_edge = 2.0f * kPi * float(k) / float(nphi);
      const glm::vec3 v_edge = -std::sin(phi_edge) * t + std::cos(phi_edge) * b;
      const float weight = (sin_hi - sin_lo) / std::min(before.distance, s.distance);
      for (int c = 0; c < 3; ++c)
        translation[c] += (weight * (s.radiance[c] - before.radiance[c])) * v_edge;
    }
  }
  gpu::IrradianceRecord record{};
  record.position_radius =
      glm::vec4(p, inverse_distances > 0 ? float(double(strata.count()) / inverse_distances)
                                         : std::numeric_limits<float>::infinity());
  record.normal = glm::vec4(n, 0.0f);
  record.irradiance = glm::vec4(cell * e, 0.0f);
  for (int c = 0; c < 3; ++c) {
    record.rotation[c] = glm::vec4(rotation[c], 0.0f);
    record.translation[c] = glm::vec4(translation[c], 0.0f);
  }
  return record;
}

}  // namespace gib::rt
