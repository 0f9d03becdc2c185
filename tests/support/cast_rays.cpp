#include "support/cast_rays.h"

#include "common/splitmix.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace gib::test {

double unitUniform(std::uint64_t& state) {
  state = splitMix64(state);
  return double(state >> 11) * 0x1.0p-53;
}

std::vector<rt::CastRay> randomCastRays(const rt::IvmTriangleSet& set, int count,
                                        std::uint64_t seed) {
  std::vector<rt::CastRay> rays;
  std::uint64_t state = seed;
  for (int i = 0; i < count; ++i) {
    // Braces: evaluated in order, so the rays are the same on every compiler.
    const glm::vec3 f{float(unitUniform(state)), float(unitUniform(state)),
                      float(unitUniform(state))};
    const double z = 2.0 * unitUniform(state) - 1.0;
    const double phi = 2.0 * std::numbers::pi * unitUniform(state);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    rt::CastRay ray;
    ray.origin = set.bounds_min + f * (set.bounds_max - set.bounds_min);
    ray.direction = glm::vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
    rays.push_back(ray);
  }
  return rays;
}

bool sameCastHit(const rt::gpu::RayCastHit& a, const rt::gpu::RayCastHit& b, float tie) {
  if (a.triangle == b.triangle) return true;
  if (a.triangle == rt::gpu::kNoRayTriangle || b.triangle == rt::gpu::kNoRayTriangle) return false;
  return std::abs(a.t - b.t) <= tie;
}

std::string describeCast(const rt::CastRay& ray, const rt::gpu::RayCastHit& hit) {
  return fmt::format("ray o=({}, {}, {}) d=({}, {}, {}): triangle {} t={}", ray.origin.x,
                     ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y, ray.direction.z,
                     hit.triangle, hit.t);
}

}  // namespace gib::test
