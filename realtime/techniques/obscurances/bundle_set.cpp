#include "realtime/techniques/obscurances/bundle_set.h"

#include "common/splitmix.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <numbers>

namespace gib::rt::obscurance {

namespace {

// The first two dimensions of Sobol's sequence, as fractions in [0, 1): the van der Corput
// sequence (bits reversed) and the second dimension's generator (each bit i of the index
// contributes the i-th row of Pascal's triangle mod 2, here built by v ^= v >> 1).
float vanDerCorput(std::uint32_t i) {
  std::uint32_t r = i;
  r = (r << 16) | (r >> 16);
  r = ((r & 0x00ff00ffu) << 8) | ((r & 0xff00ff00u) >> 8);
  r = ((r & 0x0f0f0f0fu) << 4) | ((r & 0xf0f0f0f0u) >> 4);
  r = ((r & 0x33333333u) << 2) | ((r & 0xccccccccu) >> 2);
  r = ((r & 0x55555555u) << 1) | ((r & 0xaaaaaaaau) >> 1);
  return float(r >> 8) * 0x1p-24f;
}

float sobolSecond(std::uint32_t i) {
  std::uint32_t r = 0;
  for (std::uint32_t v = 1u << 31; i != 0; i >>= 1, v ^= v >> 1)
    if (i & 1u) r ^= v;
  return float(r >> 8) * 0x1p-24f;
}

// A uniform number in [0, 1) from (seed, stream, index): 24 bits, every value exact.
float uniform(std::uint32_t seed, std::uint32_t stream, std::uint32_t index) {
  const std::uint64_t h = splitMix64((std::uint64_t(seed) << 32) ^ (std::uint64_t(stream) << 24) ^
                                     std::uint64_t(index));
  return float(h >> 40) * 0x1p-24f;
}

// A uniformly random rotation from three uniform numbers (Shoemake, "Uniform random rotations",
// Graphics Gems III): a unit quaternion uniform on the 3-sphere.
glm::quat randomRotation(float u1, float u2, float u3) {
  const float two_pi = 2.0f * std::numbers::pi_v<float>;
  const float a = std::sqrt(1.0f - u1), b = std::sqrt(u1);
  return glm::quat(b * std::cos(two_pi * u3), a * std::sin(two_pi * u2), a * std::cos(two_pi * u2),
                   b * std::sin(two_pi * u3));
}

}  // namespace

std::vector<PeelBundle> bundleSet(int count, std::uint32_t seed) {
  const glm::quat rotation =
      randomRotation(uniform(seed, 0, 0), uniform(seed, 0, 1), uniform(seed, 0, 2));
  std::vector<PeelBundle> bundles(std::size_t(std::max(count, 0)));
  for (std::uint32_t i = 0; i < bundles.size(); ++i) {
    const float z = vanDerCorput(i);
    const float phi = 2.0f * std::numbers::pi_v<float> * sobolSecond(i);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const glm::vec3 on_hemisphere(r * std::cos(phi), r * std::sin(phi), z);
    PeelBundle& b = bundles[i];
    b.direction = glm::normalize(rotation * on_hemisphere);
    b.offset = {uniform(seed, 1, i), uniform(seed, 2, i)};
  }
  return bundles;
}

}  // namespace gib::rt::obscurance
