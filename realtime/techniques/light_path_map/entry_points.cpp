#include "realtime/techniques/light_path_map/entry_points.h"

#include "common/luminance_shared.h"
#include "common/splitmix.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

namespace gib::rt::lpm {

namespace {

// A stream of uniform numbers in [0, 1) from one key: SplitMix64 over a counter.
class UniformStream {
 public:
  explicit UniformStream(std::uint64_t key) : state_(splitMixFinalise(key)) {}
  float next() {
    state_ += kGoldenGamma;
    return float(splitMixFinalise(state_) >> 40) * 0x1p-24f;  // 24 bits: exact, below 1
  }

 private:
  std::uint64_t state_;
};

std::uint64_t streamKey(std::uint32_t seed, std::uint32_t a, std::uint32_t b) {
  return splitMix64((std::uint64_t(seed) << 32) ^ a) ^ (std::uint64_t(b) * kGoldenGamma);
}

float albedoLuminance(const scene::Rgb& albedo) {
  return float(kLuminanceRed * albedo.r + kLuminanceGreen * albedo.g + kLuminanceBlue * albedo.b);
}

// Cosine-distributed direction about n: a uniform point of the unit disk lifted to the
// hemisphere (the book's construction; the disk point by polar mapping instead of rejection, so
// a walk uses a fixed count of numbers per bounce).
glm::vec3 cosineDirection(const glm::vec3& n, float u1, float u2) {
  const glm::vec3 t = glm::normalize(std::abs(n.x) > 0.9f ? glm::cross(n, glm::vec3(0, 1, 0))
                                                          : glm::cross(n, glm::vec3(1, 0, 0)));
  const glm::vec3 b = glm::cross(n, t);
  const float r = std::sqrt(u1), phi = 2.0f * std::numbers::pi_v<float> * u2;
  const float x = r * std::cos(phi), y = r * std::sin(phi);
  return x * t + y * b + std::sqrt(std::max(0.0f, 1.0f - x * x - y * y)) * n;
}

void splitNode(const std::vector<EntryPoint>& points, std::vector<int>& indices, std::size_t begin,
               std::size_t end, int first_cluster, int clusters, std::vector<int>& cluster_of) {
  if (clusters == 1) {
    for (std::size_t i = begin; i < end; ++i) cluster_of[std::size_t(indices[i])] = first_cluster;
    return;
  }
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (std::size_t i = begin; i < end; ++i) {
    lo = glm::min(lo, points[std::size_t(indices[i])].position);
    hi = glm::max(hi, points[std::size_t(indices[i])].position);
  }
  const glm::vec3 extent = hi - lo;
  const int axis =
      extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  const int left_clusters = clusters / 2;
  // Points in proportion to clusters, so that every leaf holds ⌊n/k⌋ or ⌈n/k⌉ of them.
  const std::size_t middle =
      begin + (end - begin) * std::size_t(left_clusters) / std::size_t(clusters);
  // Ties broken by index: the same split on every standard library.
  std::nth_element(indices.begin() + std::ptrdiff_t(begin),
                   indices.begin() + std::ptrdiff_t(middle), indices.begin() + std::ptrdiff_t(end),
                   [&](int a, int b) {
                     const float pa = points[std::size_t(a)].position[axis];
                     const float pb = points[std::size_t(b)].position[axis];
                     return pa < pb || (pa == pb && a < b);
                   });
  splitNode(points, indices, begin, middle, first_cluster, left_clusters, cluster_of);
  splitNode(points, indices, middle, end, first_cluster + left_clusters, clusters - left_clusters,
            cluster_of);
}

// A point in the K-means space: position and the normal scaled by `normal_scale`.
struct Feature {
  glm::vec3 p{0.0f}, n{0.0f};
};

float normalScale(const std::vector<EntryPoint>& points) {
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const EntryPoint& e : points) {
    lo = glm::min(lo, e.position);
    hi = glm::max(hi, e.position);
  }
  return points.empty() ? 0.0f : 0.1f * glm::length(hi - lo);
}

float squaredDistance(const Feature& a, const Feature& b) {
  const glm::vec3 dp = a.p - b.p, dn = a.n - b.n;
  return glm::dot(dp, dp) + glm::dot(dn, dn);
}

std::vector<Feature> features(const std::vector<EntryPoint>& points) {
  const float scale = normalScale(points);
  std::vector<Feature> f(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    f[i] = {points[i].position, scale * points[i].normal};
  return f;
}

// Each cluster's mean feature; a cluster without members keeps `centroids[c]`.
void moveCentroids(const std::vector<Feature>& f, const std::vector<int>& cluster_of,
                   std::vector<Feature>& centroids) {
  std::vector<Feature> sum(centroids.size());
  std::vector<int> count(centroids.size(), 0);
  for (std::size_t i = 0; i < f.size(); ++i) {
    const std::size_t c = std::size_t(cluster_of[i]);
    sum[c].p += f[i].p;
    sum[c].n += f[i].n;
    ++count[c];
  }
  for (std::size_t c = 0; c < centroids.size(); ++c)
    if (count[c] > 0) centroids[c] = {sum[c].p / float(count[c]), sum[c].n / float(count[c])};
}

}  // namespace

std::vector<EntryPoint> sampleEntryPoints(const std::vector<atlas::AtlasTriangle>& triangles,
                                          int count, std::uint32_t seed) {
  std::vector<double> running(triangles.size());
  double sum = 0;
  for (std::size_t i = 0; i < triangles.size(); ++i) running[i] = sum += triangles[i].area;
  std::vector<EntryPoint> points;
  if (sum <= 0) return points;
  points.reserve(std::size_t(count));
  for (int i = 0; i < count; ++i) {
    UniformStream u(streamKey(seed, std::uint32_t(i), 0));
    const double selection = double(u.next()) * sum;
    // The first triangle whose running sum reaches the selection value (zero-area ones never).
    const std::size_t j =
        std::size_t(std::upper_bound(running.begin(), running.end(), selection) - running.begin());
    const atlas::AtlasTriangle& t = triangles[std::min(j, triangles.size() - 1)];
    float r2 = u.next(), r3 = u.next();
    if (r2 + r3 > 1.0f) {
      r2 = 1.0f - r2;
      r3 = 1.0f - r3;
    }
    points.push_back({t.p[0] + r2 * (t.p[1] - t.p[0]) + r3 * (t.p[2] - t.p[0]), t.normal,
                      int(std::min(j, triangles.size() - 1))});
  }
  return points;
}

std::vector<int> clusterEntryPoints(const std::vector<EntryPoint>& points, int clusters) {
  std::vector<int> indices(points.size());
  std::iota(indices.begin(), indices.end(), 0);
  std::vector<int> cluster_of(points.size(), 0);
  if (!points.empty()) splitNode(points, indices, 0, points.size(), 0, clusters, cluster_of);
  return cluster_of;
}

LightWalks traceLightWalks(const scene::RayCaster& caster, const scene::Scene& scene,
                           const std::vector<atlas::AtlasTriangle>& triangles,
                           const std::vector<EntryPoint>& entries,
                           const std::vector<int>& cluster_of_entry, int paths_per_entry,
                           double total_area, std::uint32_t seed, int max_vertices) {
  // The atlas triangles follow the meshes' order: mesh m's triangle k is first[m] + k.
  std::vector<std::size_t> first(scene.meshes.size(), 0);
  for (std::size_t m = 1; m < scene.meshes.size(); ++m)
    first[m] = first[m - 1] + scene.meshes[m - 1].triangles.size();

  LightWalks walks;
  std::vector<std::size_t> order(entries.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return cluster_of_entry[a] < cluster_of_entry[b];
  });
  const float share = 1.0f / float(paths_per_entry);
  const float epsilon = caster.rayEpsilon();
  for (std::size_t i : order) {
    const EntryPoint& entry = entries[i];
    const int cluster = cluster_of_entry[i];
    const scene::Rgb& entry_albedo =
        scene.materials[triangles[std::size_t(entry.triangle)].material].diffuse;
    // The entry point's own light, once for all its paths: unit irradiance reflected, S·f₁.
    const glm::vec3 entry_intensity =
        float(total_area) * entry_albedo * std::numbers::inv_pi_v<float>;
    if (glm::length(entry_intensity) > 0)
      walks.lights.push_back({entry.position, entry.normal, entry_intensity, cluster});
    walks.path_vertices += paths_per_entry;
    for (int j = 0; j < paths_per_entry; ++j) {
      UniformStream u(streamKey(seed, std::uint32_t(i), std::uint32_t(j) + 1));
      glm::vec3 position = entry.position, normal = entry.normal;
      glm::vec3 albedo = entry_albedo, throughput(1.0f);
      for (int vertices = 1; max_vertices <= 0 || vertices < max_vertices; ++vertices) {
        const float continuation = std::min(albedoLuminance(albedo), 1.0f);
        if (!(u.next() < continuation)) break;
        throughput *= albedo / continuation;
        const glm::vec3 direction = cosineDirection(normal, u.next(), u.next());
        const scene::RayHit hit = caster.intersect(position + epsilon * normal, direction, 0.0f);
        if (!hit.valid()) break;
        const atlas::AtlasTriangle& t = triangles[first[hit.mesh] + hit.triangle];
        if (glm::dot(t.normal, direction) >= 0) break;  // a back face: no atlas side to light
        position = position + epsilon * normal + hit.t * direction;
        normal = t.normal;
        albedo = scene.materials[t.material].diffuse;
        ++walks.path_vertices;
        const glm::vec3 intensity =
            float(total_area) * share * throughput * albedo * std::numbers::inv_pi_v<float>;
        if (glm::length(intensity) > 0)
          walks.lights.push_back({position, normal, intensity, cluster});
      }
    }
  }
  return walks;
}

std::vector<int> clusterEntryPointsKMeans(const std::vector<EntryPoint>& points, int clusters,
                                          int iterations) {
  std::vector<int> cluster_of = clusterEntryPoints(points, clusters);
  const std::vector<Feature> f = features(points);
  auto centroids = std::vector<Feature>(std::size_t(clusters));
  moveCentroids(f, cluster_of, centroids);
  for (int iteration = 0; iteration < iterations; ++iteration) {
    bool changed = false;
    for (std::size_t i = 0; i < f.size(); ++i) {
      int best = cluster_of[i];
      float best_distance = squaredDistance(f[i], centroids[std::size_t(best)]);
      for (int c = 0; c < clusters; ++c) {
        const float d = squaredDistance(f[i], centroids[std::size_t(c)]);
        if (d < best_distance || (d == best_distance && c < best)) {
          best = c;
          best_distance = d;
        }
      }
      changed |= best != cluster_of[i];
      cluster_of[i] = best;
    }
    moveCentroids(f, cluster_of, centroids);
    if (!changed) break;
  }
  return cluster_of;
}

double clusteringCost(const std::vector<EntryPoint>& points, const std::vector<int>& cluster_of,
                      int clusters) {
  const std::vector<Feature> f = features(points);
  auto centroids = std::vector<Feature>(std::size_t(clusters));
  moveCentroids(f, cluster_of, centroids);
  double cost = 0;
  for (std::size_t i = 0; i < f.size(); ++i)
    cost += squaredDistance(f[i], centroids[std::size_t(cluster_of[i])]);
  return cost;
}

}  // namespace gib::rt::lpm
