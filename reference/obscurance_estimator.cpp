#include "reference/obscurance_estimator.h"

#include "common/parallel_for.h"
#include "reference/path_sampler.h"
#include "reference/sampling.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace gib::ref {

namespace {

// Points handed to a thread at a time by estimateObscurances.
constexpr std::size_t kPointChunk = 16;

}  // namespace

ObscuranceEstimator::ObscuranceEstimator(const scene::Scene& scene,
                                         const scene::ObscuranceDefinition& definition)
    : scene_(scene),
      definition_(definition),
      owned_embree_(std::make_unique<EmbreeScene>(scene)),
      owned_triangles_(std::make_unique<TriangleTable>(scene)),
      embree_(owned_embree_.get()),
      triangles_(owned_triangles_.get()),
      d_max_(scene::maxDistance(scene, definition)),
      average_albedo_(scene::sceneAverages(scene).albedo) {}

ObscuranceEstimator::ObscuranceEstimator(const scene::Scene& scene,
                                         const scene::ObscuranceDefinition& definition,
                                         const EmbreeScene& embree, const TriangleTable& triangles)
    : scene_(scene),
      definition_(definition),
      embree_(&embree),
      triangles_(&triangles),
      d_max_(scene::maxDistance(scene, definition)),
      average_albedo_(scene::sceneAverages(scene).albedo) {}

ObscuranceEstimator::~ObscuranceEstimator() = default;

glm::vec3 ObscuranceEstimator::sample(const glm::vec3& point, const glm::vec3& normal,
                                      glm::vec2 u) const {
  // Importance sampling by cos θ/π cancels the cosine and the 1/π of eq. 10.2 (eq. 10.6): the
  // ray's value is ρ(d), or ρ(d)·a(y) in the spectral method.
  const glm::vec3 direction = Frame(normal).toWorld(sampleCosineHemisphere(u));
  // The ray leaves from just off the surface, as the path tracer's do, so that it does not find
  // the surface it leaves; d is measured from the point itself, so the offset does not shorten it.
  const glm::vec3 origin = point + embree_->rayEpsilon() * normal;
  const Hit hit = embree_->intersect(origin, direction);
  float d = std::numeric_limits<float>::infinity();
  scene::Rgb hit_albedo(0.0f);
  if (hit.valid()) {
    d = glm::length(origin + hit.t * direction - point);
    const TriangleRecord& triangle = (*triangles_)[triangles_->globalIndex(hit.mesh, hit.triangle)];
    hit_albedo = scene::obscuranceAlbedo(scene_.materials[triangle.material]);
  }
  return scene::obscuranceSample(definition_.mode == scene::ObscuranceMode::kSpectral,
                                 int(definition_.falloff), d, d_max_, hit_albedo, average_albedo_);
}

std::vector<ObscuranceEstimate> estimateObscurances(const ObscuranceEstimator& estimator,
                                                    std::span<const ObscurancePoint> points,
                                                    std::uint32_t rays, std::uint64_t seed,
                                                    int threads) {
  if (rays < 2)
    throw std::invalid_argument("estimateObscurances needs 2 rays or more for a standard error");
  std::vector<ObscuranceEstimate> estimates(points.size());
  parallelFor(points.size(), threads, kPointChunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      glm::dvec3 sum(0.0), sum_squares(0.0);
      for (std::uint32_t j = 0; j < rays; ++j) {
        // One replica per ray: each ray is sample 0 of its own scramble, independent of the others.
        PathSampler sampler(seed, std::uint32_t(i), j, rays);
        sampler.startVertex(0);
        const glm::dvec3 value(estimator.sample(points[i].position, points[i].normal,
                                                sampler.get2D(VertexDimension::kDirection)));
        sum += value;
        sum_squares += value * value;
      }
      ObscuranceEstimate& e = estimates[i];
      e.rays = rays;
      e.mean = sum / double(rays);
      const glm::dvec3 variance =
          glm::max(sum_squares - double(rays) * e.mean * e.mean, glm::dvec3(0.0)) /
          double(rays - 1);
      e.standard_error = glm::sqrt(variance / double(rays));
    }
  });
  return estimates;
}

}  // namespace gib::ref
