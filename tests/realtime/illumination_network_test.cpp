// The illumination network (book §9.6): the visibility network against a brute-force walk on the
// CPU, one iteration against the same discretisation evaluated on the CPU, geometric convergence,
// albedo 0 (only the sky, attenuated), a lossless cloud under a uniform sky (invisible), and the
// k-iteration image against the reference limited to k + 1 bounces.
#include "realtime/techniques/illumination_network/illumination_network_technique.h"

#include "realtime/gl/pass_profiler.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/render_target.h"
#include "reference/phase_function.h"
#include "scene/builtin_scenes.h"
#include "scene/camera.h"
#include "scene/medium.h"
#include "support/gl_test_context.h"
#include "support/medium_march.h"
#include "support/particle_lighting.h"
#include "support/technique_frame.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace gib::rt {
namespace {

// A prepared network over `scene` at size², with the technique at hand.
struct Network {
  std::unique_ptr<GpuScene> gpu;
  std::unique_ptr<IlluminationNetworkTechnique> technique;

  Network(const scene::Scene& scene, int size, const std::vector<std::string>& set) {
    const TechniqueInfo& info = findTechnique("illumination_network");
    gpu = std::make_unique<GpuScene>(scene, size, size);
    technique = std::make_unique<IlluminationNetworkTechnique>(
        parseParameters(info.parameters, set, info.name));
    technique->prepare(*gpu, size, size);
  }
  void iterate(int steps) {
    gl::PassProfiler unmeasured;
    for (int i = 0; i < steps; ++i) technique->step(unmeasured);
  }
  image::Image render() {
    RenderTarget target(gpu->width(), gpu->height());
    gl::PassProfiler unmeasured;
    Frame frame{target, unmeasured, 0, 1};
    target.clear(0, 0, 0);
    technique->render(frame);
    return target.read();
  }
};

scene::Scene cloud(const std::vector<std::string>& assignments) {
  return scene::loadScene("cloud", assignments);
}

class IlluminationNetwork : public test::GlTest {};

// V[p, i] is, for every particle and direction, the particle whose sphere the line from p's
// centre along ω_i crosses with the nearest centre ahead, and its whole chord's opacity. Pairs
// whose choice hinges on a float tie (two centres within 1e-4 along the line, or a line grazing
// a sphere) are allowed to differ; they are under 1% of the pairs.
TEST_F(IlluminationNetwork, VisibilityNetworkMatchesABruteForceWalkOnTheCpu) {
  const scene::Scene s = cloud({"particles=96"});
  Network network(s, 16, {"directions=24"});
  const std::vector<gpu::NetworkLink> links = network.technique->visibility();
  const std::vector<glm::vec4>& directions = network.technique->directions();
  const auto& particles = s.medium.particles;
  const std::size_t n = particles.size(), d = directions.size();
  ASSERT_EQ(links.size(), n * d);
  int sky = 0, ambiguous = 0;
  for (std::size_t p = 0; p < n; ++p)
    for (std::size_t i = 0; i < d; ++i) {
      const glm::dvec3 omega(directions[i]);
      int best = -1;
      double best_t = 1e300, best_d2 = 0, runner_up = 1e300;
      bool grazing = false;
      for (std::size_t q = 0; q < n; ++q) {
        if (q == p) continue;
        const glm::dvec3 v = glm::dvec3(particles[q].centre) - glm::dvec3(particles[p].centre);
        const double t = glm::dot(v, omega);
        const double d2 = glm::dot(v, v) - t * t;
        const double r2 = double(particles[q].radius) * particles[q].radius;
        if (t <= 0 || d2 >= r2) continue;
        if (std::abs(d2 - r2) < 1e-4) grazing = true;
        if (t < best_t) {
          runner_up = best_t;
          best = int(q), best_t = t, best_d2 = d2;
        } else {
          runner_up = std::min(runner_up, t);
        }
      }
      const gpu::NetworkLink& link = links[p * d + i];
      if ((best >= 0 && runner_up - best_t < 1e-4) || grazing) {
        ++ambiguous;
        continue;
      }
      ASSERT_EQ(link.particle, best) << "particle " << p << " direction " << i;
      if (best < 0) {
        ++sky;
        EXPECT_EQ(link.opacity, 0.0f);
        continue;
      }
      const auto& q = particles[std::size_t(best)];
      const double chord =
          q.density * q.radius * [&] {  // ∫ (1 − √(d² + s²)/r) ds over the chord, per unit τ·r
            const double dd = std::sqrt(best_d2), r = q.radius;
            const double w = std::sqrt(r * r - best_d2);
            const double f = w * r + (dd > 0 ? best_d2 * std::asinh(w / dd) : 0);
            return (2 * w - f / r) / r;
          }();
      EXPECT_NEAR(link.opacity, 1.0 - std::exp(-chord), 2e-5) << p << " " << i;
    }
  EXPECT_LT(ambiguous, int(n * d) / 100);
  EXPECT_GT(sky, 0);                   // particles at the fringe see the sky
  EXPECT_LT(sky, int(n * d) * 3 / 4);  // and most see other particles
}

// W[d, i] on the CPU from the reference's Henyey–Greenstein, each column summing to one.
std::vector<double> cpuPhaseMatrix(const std::vector<glm::vec4>& directions, float g) {
  const std::size_t n = directions.size();
  std::vector<double> w(n * n);
  for (std::size_t i = 0; i < n; ++i) {
    double sum = 0;
    for (std::size_t d = 0; d < n; ++d)
      sum += w[d * n + i] =
          ref::henyeyGreenstein(glm::dot(glm::vec3(directions[d]), glm::vec3(directions[i])), g);
    for (std::size_t d = 0; d < n; ++d) w[d * n + i] /= sum;
  }
  return w;
}

// One iteration of the GPU network equals the discretised equations evaluated on the CPU from the
// same V, E and I₀: J = E + a·Σ_d I₀ W, then I₁ gathered along each chain (with g = 0.5, so the
// phase matrix is not constant). Also I₀ is the sky through each chain.
TEST_F(IlluminationNetwork, OneIterationEqualsSingleScatteringOfTheSameDiscretisation) {
  const scene::Scene s = cloud({"particles=80", "g=0.5"});
  Network network(s, 16, {"directions=32"});
  const std::vector<gpu::NetworkLink> links = network.technique->visibility();
  const std::vector<glm::vec4> e = network.technique->emission();
  const std::vector<glm::vec4> i0 = network.technique->incoming();
  network.iterate(1);
  const std::vector<glm::vec4> i1 = network.technique->incoming();
  const std::vector<glm::vec4>& directions = network.technique->directions();
  const std::size_t n = s.medium.particles.size(), d = directions.size();
  const std::vector<double> w = cpuPhaseMatrix(directions, 0.5f);
  const glm::dvec3 albedo(s.medium.albedo), sky(s.sky_radiance);
  auto gather = [&](std::size_t p, std::size_t i, auto&& source) {
    glm::dvec3 radiance(0.0);
    double transmittance = 1;
    for (std::size_t current = p;;) {
      const gpu::NetworkLink& link = links[current * d + i];
      if (link.particle < 0) return radiance + transmittance * sky;
      radiance += transmittance * double(link.opacity) * source(std::size_t(link.particle), i);
      transmittance *= 1.0 - link.opacity;
      current = std::size_t(link.particle);
    }
  };
  double largest = 0;
  for (std::size_t p = 0; p < n; ++p)
    for (std::size_t i = 0; i < d; ++i) {
      const glm::dvec3 expected0 =
          gather(p, i, [](std::size_t, std::size_t) { return glm::dvec3(0); });
      const glm::dvec3 expected1 = gather(p, i, [&](std::size_t q, std::size_t k) {
        glm::dvec3 j(e[q * d + k]);
        for (std::size_t m = 0; m < d; ++m) j += albedo * w[m * d + k] * glm::dvec3(i0[q * d + m]);
        return j;
      });
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(i0[p * d + i][c], expected0[c], 1e-5 * (1 + expected0[c]));
        EXPECT_NEAR(i1[p * d + i][c], expected1[c], 1e-4 * expected1[c] + 1e-6) << p << " " << i;
      }
      largest = std::max(largest, expected1.x - expected0.x);
    }
  EXPECT_GT(largest, 0.05) << "the iteration added no light: the test would not see a wrong sum";
}

// Successive iterations change I by geometrically shrinking amounts, each step's change below the
// albedo times the previous one's (light leaves the chains or is absorbed at every scattering).
TEST_F(IlluminationNetwork, IterationConvergesGeometricallyWithARatioBelowTheAlbedo) {
  const scene::Scene s = cloud({"particles=128"});
  Network network(s, 16, {"directions=32"});
  std::vector<glm::vec4> previous = network.technique->incoming();
  std::vector<double> change;
  for (int k = 1; k <= 8; ++k) {
    network.iterate(1);
    const std::vector<glm::vec4> current = network.technique->incoming();
    double sum = 0;
    for (std::size_t j = 0; j < current.size(); ++j)
      for (int c = 0; c < 3; ++c) sum += std::abs(current[j][c] - previous[j][c]);
    change.push_back(sum);
    previous = current;
  }
  for (std::size_t k = 1; k < change.size(); ++k) {
    EXPECT_GT(change[k], 0.0);
    EXPECT_LT(change[k] / change[k - 1], s.medium.albedo.g) << "iteration " << k + 1;
  }
}

// Albedo 0: nothing is emitted or scattered, iterations change nothing, and every pixel is the
// sky times the cloud's transmittance along the pixel's ray (marched through the reference
// layer's density grid), within 2e-3.
TEST_F(IlluminationNetwork, AlbedoZeroShowsOnlyTheSkyThroughTheCloud) {
  const scene::Scene s = cloud({"particles=128", "albedo=0"});
  constexpr int kSize = 32;
  Network network(s, kSize, {"directions=16"});
  for (const glm::vec4& value : network.technique->emission())
    EXPECT_EQ(glm::vec3(value), glm::vec3(0));
  const std::vector<glm::vec4> before = network.technique->incoming();
  network.iterate(3);
  EXPECT_EQ(network.technique->incoming(), before);
  const image::Image image = network.render();
  const scene::DensityGrid medium(s.medium.particles);
  const scene::CameraFrame frame = scene::makeCameraFrame(s.camera, kSize, kSize);
  int attenuated = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const glm::vec3 direction =
          scene::cameraRayDirection(frame, kSize, kSize, x + 0.5f, y + 0.5f);
      const double depth =
          test::marchedOpticalDepth(medium, s.camera.position, direction, 0.0, 30.0, 6000);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(image.pixel(x, y)[c], s.sky_radiance[c] * std::exp(-depth), 2e-3)
            << x << "," << y;
      if (depth > 1) ++attenuated;
    }
  EXPECT_GT(attenuated, kSize * kSize / 8);
}

// Albedo 1 under a uniform sky and no other light: the cloud neither absorbs nor emits, so once
// the iteration has converged it is invisible, every pixel the sky within 1%. (The densities are
// quartered so that 40 iterations converge: at the cloud's full optical depth, light diffuses
// through a lossless core over hundreds.) Spherical billboards model single scattering only, so
// a lossless cloud is darker than the sky there by design.
TEST_F(IlluminationNetwork, ALosslessCloudUnderAUniformSkyIsInvisible) {
  scene::Scene s = cloud({"particles=128", "albedo=1", "g=0.3"});
  s.directional_lights.clear();
  for (scene::MediumParticle& p : s.medium.particles) p.density *= 0.25f;
  constexpr int kSize = 32;
  Network network(s, kSize, {"directions=32"});
  network.iterate(40);
  const image::Image image = network.render();
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(image.pixel(x, y)[c], s.sky_radiance[c], 0.01 * s.sky_radiance[c])
            << x << "," << y;
}

// The scattered light after 1 and after 24 iterations, its ratio and its relMSE each: a family
// of four at 1%.
constexpr test::TestFamily kScatteredLightFamily(0.01, 4);

// k iterations against the reference limited to k + 1 bounces (the technique's path class), and
// the converged network against the full reference, on a cloud of 256 particles at 32², 64 spp
// in 16 replicas (15 degrees of freedom). The densities are quartered, as in the lossless test,
// so that lighting the particles at their centres, which the network does at every scattering,
// costs little: centreLightingAllowance (4.4% of the scattered light here, 8.8% in a pixel).
// The chains stand in for the lines' transmittance as the volume shadow does, from a particle's
// centre with its own density left out; what else sets a chain apart from its line has no
// bound here, and the same allowance is asked of it. The sky transmitted through the medium is
// exact (the albedo-0 test); the scattered light's sum and the relMSE less the reference's noise
// are held to the allowance plus their standard errors' family-wise bound (1%, four estimates).
// At one iteration an order of scattering too few takes 25% of the scattered light away, one
// too many adds 10%, the fill light left out of the view shading takes 7.5%; the lights' light
// off by a small scale is the billboards' one-particle test's to find (the same view shading),
// the scattering's the lossless test's.
TEST_F(IlluminationNetwork, MatchesTheReferenceOfItsPathClass) {
  scene::Scene s = cloud({"particles=256"});
  for (scene::MediumParticle& p : s.medium.particles) p.density *= 0.25f;
  scene::Scene absorbing = s;
  absorbing.medium.albedo = scene::Rgb(0.0f);
  constexpr int kSize = 32;
  const image::Image transmitted = Network(absorbing, kSize, {}).render();
  const test::CentreLightingAllowance allowance = test::centreLightingAllowance(s.medium.particles);
  for (int iterations : {1, 24}) {
    Network network(s, kSize, {});
    network.iterate(iterations);
    ASSERT_EQ(network.technique->pathClass().max_bounces, iterations + 1);
    const image::Image image = network.render();
    const scene::PathClass path_class =
        iterations == 24 ? scene::PathClass{} : network.technique->pathClass();
    const ref::RenderResult reference = test::renderClassReference(s, kSize, 64, path_class, 16);
    const test::ScatteredLightMatch match =
        test::matchScatteredLight(reference, image, transmitted, allowance);
    const std::string k = std::to_string(iterations);
    RecordProperty("scattered_light_ratio_" + k, std::to_string(match.ratio.mean));
    RecordProperty("relmse_less_noise_" + k, std::to_string(match.relmse.mean));
    std::printf(
        "%d iterations: scattered light ratio %.4f ± %.4f (allowance %.4f); relMSE less "
        "noise %.6f ± %.6f (allowance %.6f)\n",
        iterations, match.ratio.mean, match.ratio.standard_error, allowance.mean, match.relmse.mean,
        match.relmse.standard_error, match.relmse_allowance);
    SCOPED_TRACE(k + " iterations");
    test::expectScatteredLightMatches(match, allowance, kScatteredLightFamily);
  }
}

}  // namespace
}  // namespace gib::rt
