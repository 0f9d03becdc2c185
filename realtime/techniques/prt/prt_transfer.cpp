#include "realtime/techniques/prt/prt_transfer.h"

#include "common/luminance_shared.h"
#include "common/parallel_for.h"
#include "common/splitmix.h"
#include "realtime/irradiance_cache/irradiance_cache_shared.h"
#include "realtime/sh/sh_basis.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace gib::rt::prt {

namespace {

// Vertices per chunk of parallelFor: a few hundred rays each, enough to amortise the counter.
constexpr std::size_t kChunk = 8;

double luminanceOf(const glm::dvec3& c) {
  return kLuminanceRed * c.r + kLuminanceGreen * c.g + kLuminanceBlue * c.b;
}

// A float in [0, 1) from the top 24 bits of a hashed counter.
float unitFloat(std::uint64_t bits) {
  return float(bits >> 40) * 0x1.0p-24f;
}

// The light a vertex's ray carries, per unit of L, split from the rest so that both bounce 1 and
// the error estimate read it: an escaping ray's direction or a hit's sub-triangle.
struct VertexRays {
  std::vector<LatticeHit> hits;                  // front faces met
  double escape_sum = 0, escape_square_sum = 0;  // luminance of ρ·(L·Y(ω)) over escaping rays
};

glm::vec3 dotLighting(const float* vector, int n, std::span<const glm::vec3> lighting) {
  glm::vec3 radiance(0.0f);
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < n; ++i) radiance[c] += lighting[std::size_t(i)][c] * vector[c * n + i];
  return radiance;
}

}  // namespace

std::pair<int, int> strataOf(int rays) {
  int rows = int(std::sqrt(double(rays)));
  while (rows > 1 && rays % rows != 0) --rows;
  return {rows, rays / rows};
}

std::vector<glm::vec3> vertexRadiance(std::span<const float> vectors, int coefficients,
                                      std::span<const glm::vec3> lighting) {
  const std::size_t dimension = 3 * std::size_t(coefficients);
  std::vector<glm::vec3> radiance(vectors.size() / dimension);
  for (std::size_t v = 0; v < radiance.size(); ++v)
    radiance[v] = dotLighting(vectors.data() + v * dimension, coefficients, lighting);
  return radiance;
}

Transfer computeTransfer(const PrtMesh& mesh, const scene::Scene& scene,
                         const scene::RayCaster& caster, const TransferSettings& settings,
                         std::span<const glm::vec3> lighting) {
  const int n = sh::shBasisCount(settings.bands);
  const std::size_t dimension = 3 * std::size_t(n);
  const std::size_t count = mesh.vertexCount();
  // Plain variables, not a structured binding: the lambda below captures them, which clang
  // before 16 refuses for bindings.
  const std::pair<int, int> strata = strataOf(settings.rays);
  const int rows = strata.first, columns = strata.second;
  const float epsilon = caster.rayEpsilon();
  const double inverse_rays = 1.0 / settings.rays;

  Transfer out;
  out.coefficients = n;
  // Bounce 1: the unoccluded part of the cosine-weighted basis, and each ray's hit kept for the
  // later bounces.
  std::vector<float> bounce(count * dimension, 0.0f);
  std::vector<VertexRays> vertex_rays(count);
  std::vector<std::size_t> hit_counts(count, 0);
  parallelFor(count, settings.threads, kChunk, [&](std::size_t begin, std::size_t end) {
    std::vector<scene::Ray> rays(std::size_t(settings.rays));
    std::vector<scene::RayHit> hits(rays.size());
    std::vector<float> basis(static_cast<std::size_t>(n));
    std::vector<double> sum(static_cast<std::size_t>(n));
    for (std::size_t v = begin; v < end; ++v) {
      const glm::vec3 normal = mesh.normals[v];
      const glm::vec3 tangent = gpu::basisTangent(normal), bitangent = gpu::basisBitangent(normal);
      const glm::vec3 origin = mesh.positions[v] + epsilon * normal;
      // Counter-based draws from the vertex index and the seed: independent of the thread count.
      const std::uint64_t stream = splitMix64(settings.seed ^ splitMix64(std::uint64_t(v)));
      for (int r = 0; r < settings.rays; ++r) {
        const std::uint64_t draw = stream + 2 * std::uint64_t(r) * kGoldenGamma;
        const float u1 = (float(r / columns) + unitFloat(splitMixFinalise(draw))) / float(rows);
        const float u2 = (float(r % columns) + unitFloat(splitMixFinalise(draw + kGoldenGamma))) /
                         float(columns);
        // Malley's method: a uniform point of the unit disc lifted to the hemisphere, pdf cosθ/π.
        const float radius = std::sqrt(u1), phi = 2.0f * std::numbers::pi_v<float> * u2;
        const float z = std::sqrt(std::max(0.0f, 1.0f - u1));
        rays[std::size_t(r)] = {origin,
                                glm::normalize(radius * std::cos(phi) * tangent +
                                               radius * std::sin(phi) * bitangent + z * normal),
                                epsilon};
      }
      caster.intersect(rays, hits, true);
      std::fill(sum.begin(), sum.end(), 0.0);
      VertexRays& record = vertex_rays[v];
      const glm::dvec3 rho(mesh.albedo[v]);
      for (std::size_t r = 0; r < rays.size(); ++r) {
        const glm::vec3 d = rays[r].direction;
        if (!hits[r].valid()) {
          sh::evaluateShBasis(d, settings.bands, basis);
          glm::dvec3 radiance(0.0);
          for (int i = 0; i < n; ++i) {
            sum[std::size_t(i)] += basis[std::size_t(i)];
            radiance += glm::dvec3(lighting[std::size_t(i)]) * double(basis[std::size_t(i)]);
          }
          const double y = luminanceOf(rho * radiance);
          record.escape_sum += y;
          record.escape_square_sum += y * y;
          continue;
        }
        ++hit_counts[v];
        const scene::Mesh& hit_mesh = scene.meshes[hits[r].mesh];
        const glm::uvec3 t = hit_mesh.triangles[hits[r].triangle];
        const glm::vec3 a = hit_mesh.positions[t[0]];
        const glm::vec3 front =
            glm::cross(hit_mesh.positions[t[1]] - a, hit_mesh.positions[t[2]] - a);
        // A back face reflects nothing here (the transfer is its front side's): the ray is only
        // blocked.
        if (glm::dot(front, d) >= 0) continue;
        record.hits.push_back(
            locate(mesh, scene, hits[r].mesh, hits[r].triangle, origin + hits[r].t * d));
      }
      float* vector = bounce.data() + v * dimension;
      for (int c = 0; c < 3; ++c)
        for (int i = 0; i < n; ++i)
          vector[c * n + i] = float(rho[c] * sum[std::size_t(i)] * inverse_rays);
    }
  });
  for (std::size_t h : hit_counts) out.rays_hit += h;
  out.rays_cast = count * std::size_t(settings.rays);

  // Later bounces: T_b(x) = ρ/rays · Σ_hits T_{b−1}(hit), interpolated linearly on the hit's
  // sub-triangle; `previous_total` is the sum over bounces before the last, which the error
  // estimate reads at the hits.
  out.vectors = bounce;
  std::vector<float> previous_total = out.vectors;
  std::vector<float> next(bounce.size());
  for (int b = 2; b <= settings.bounces; ++b) {
    previous_total = out.vectors;
    parallelFor(count, settings.threads, 64, [&](std::size_t begin, std::size_t end) {
      std::vector<double> sum(dimension);
      for (std::size_t v = begin; v < end; ++v) {
        std::fill(sum.begin(), sum.end(), 0.0);
        for (const LatticeHit& hit : vertex_rays[v].hits)
          for (int k = 0; k < 3; ++k) {
            const float* source = bounce.data() + hit.vertices[std::size_t(k)] * dimension;
            const double w = hit.weights[std::size_t(k)];
            for (std::size_t i = 0; i < dimension; ++i) sum[i] += w * source[i];
          }
        const glm::vec3 rho = mesh.albedo[v];
        float* target = next.data() + v * dimension;
        for (std::size_t i = 0; i < dimension; ++i)
          target[i] = float(double(rho[int(i / std::size_t(n))]) * sum[i] * inverse_rays);
      }
    });
    bounce.swap(next);
    for (std::size_t i = 0; i < out.vectors.size(); ++i) out.vectors[i] += bounce[i];
  }

  // The per-ray estimates of the vertex's radiance: ρ·(L·Y(ω)) for an escaping ray, ρ·(L·T) of
  // the hit point for a ray that meets a front face (T the transfer of the bounces before the
  // last, 0 for bounces = 1), 0 for a back face. Their sample variance over rays is that of
  // independent draws; stratification only lowers the true one, so this is an upper estimate.
  const std::vector<glm::vec3> hit_radiance =
      settings.bounces > 1 ? vertexRadiance(previous_total, n, lighting) : std::vector<glm::vec3>();
  double variance_sum = 0, square_sum = 0;
  for (std::size_t v = 0; v < count; ++v) {
    const VertexRays& record = vertex_rays[v];
    double s = record.escape_sum, s2 = record.escape_square_sum;
    if (settings.bounces > 1)
      for (const LatticeHit& hit : record.hits) {
        glm::dvec3 radiance(0.0);
        for (int k = 0; k < 3; ++k)
          radiance += double(hit.weights[std::size_t(k)]) *
                      glm::dvec3(hit_radiance[hit.vertices[std::size_t(k)]]);
        const double y = luminanceOf(glm::dvec3(mesh.albedo[v]) * radiance);
        s += y, s2 += y * y;
      }
    const double mean = s * inverse_rays;
    const double sample_variance =
        settings.rays > 1 ? std::max(0.0, (s2 - s * mean) / (settings.rays - 1)) : 0.0;
    variance_sum += sample_variance * inverse_rays;
    square_sum += mean * mean;
  }
  out.monte_carlo_error = square_sum > 0 ? std::sqrt(variance_sum / square_sum) : 0.0;
  return out;
}

}  // namespace gib::rt::prt
