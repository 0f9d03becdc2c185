// The CPU spherical-harmonic mathematics of pre-computed radiance transfer (realtime/sh/
// sh_basis.h, sh_rotation.h): evaluating the basis for 3, 6 and 8 bands, and turning 6 bands of
// RGB coefficients (the recurrences from a 3×3 matrix and the product, as when the environment
// turns every frame; the product alone; the cached +y rotation). sh_projection_bench.cpp
// projects maps.
#include "common/splitmix.h"
#include "realtime/sh/sh_basis.h"
#include "realtime/sh/sh_rotation.h"

#include <benchmark/benchmark.h>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <numbers>
#include <vector>

namespace {

using namespace gib;

double uniform(std::uint64_t i) {
  return double(splitMix64(17 + i * kGoldenGamma) >> 11) * 0x1p-53;
}

std::vector<glm::vec3> directions(int count) {
  std::vector<glm::vec3> out;
  for (int i = 0; i < count; ++i) {
    const double z = 2 * uniform(std::uint64_t(2 * i)) - 1;
    const double phi = 2 * std::numbers::pi * uniform(std::uint64_t(2 * i + 1));
    const double s = std::sqrt(1 - z * z);
    out.emplace_back(float(s * std::cos(phi)), float(s * std::sin(phi)), float(z));
  }
  return out;
}

void BM_ShBasis(benchmark::State& state) {
  const int bands = int(state.range(0));
  const std::vector<glm::vec3> d = directions(1024);
  std::vector<float> y(std::size_t(rt::sh::shBasisCount(bands)));
  for (auto _ : state)
    for (const glm::vec3& direction : d) {
      rt::sh::evaluateShBasis(direction, bands, y);
      benchmark::DoNotOptimize(y.data());
    }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(d.size()));
}
BENCHMARK(BM_ShBasis)->Arg(3)->Arg(6)->Arg(8);

std::vector<glm::vec3> coefficients(int bands) {
  std::vector<glm::vec3> c(std::size_t(rt::sh::shBasisCount(bands)));
  for (std::size_t i = 0; i < c.size(); ++i)
    c[i] = glm::vec3(float(uniform(3 * i)), float(uniform(3 * i + 1)), float(uniform(3 * i + 2)));
  return c;
}

// A general rotation: the band matrices from the 3×3 matrix, then RGB coefficients through them.
void BM_ShRotation(benchmark::State& state) {
  const int bands = int(state.range(0));
  const std::vector<glm::vec3> c = coefficients(bands);
  std::vector<glm::vec3> out(c.size());
  const glm::mat3 r = glm::mat3_cast(glm::normalize(glm::quat(0.3f, -0.5f, 0.7f, 0.2f)));
  for (auto _ : state) {
    const rt::sh::ShRotation rotation(r, bands);
    rotation.apply(c, out);
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(BM_ShRotation)->Arg(6);

// Only the product with band matrices built once.
void BM_ShRotationApply(benchmark::State& state) {
  const int bands = int(state.range(0));
  const std::vector<glm::vec3> c = coefficients(bands);
  std::vector<glm::vec3> out(c.size());
  const rt::sh::ShRotation rotation(
      glm::mat3_cast(glm::normalize(glm::quat(0.3f, -0.5f, 0.7f, 0.2f))), bands);
  for (auto _ : state) {
    rotation.apply(c, out);
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(BM_ShRotationApply)->Arg(6);

void BM_ShRotateAboutY(benchmark::State& state) {
  const int bands = int(state.range(0));
  std::vector<glm::vec3> c = coefficients(bands);
  for (auto _ : state) {
    rt::sh::rotateAboutY(c, bands, 0.01f);
    benchmark::DoNotOptimize(c.data());
  }
}
BENCHMARK(BM_ShRotateAboutY)->Arg(6);

}  // namespace
