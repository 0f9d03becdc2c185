// The CPU half of the light path map's preprocessing (book §8.4.1): entry points sampled
// uniformly over the scene's surface area, grouped into clusters by an object-median kd-tree, and
// the random walks from them whose visited points become virtual lights. Pure functions of the
// scene, the counts and the seed: no GL, so tests check them directly.
#pragma once

#include "realtime/atlas/atlas_layout.h"
#include "scene/ray_caster.h"
#include "scene/scene.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace gib::rt::lpm {

struct EntryPoint {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f};  // unit geometric normal of its triangle (its front side)
  int triangle = 0;        // index into the atlas triangles
};

// `count` points with density 1/S over the triangles of total area S, the book's method: a
// triangle chosen with probability A_i/S by the running sum of areas, then v1 + r2(v2 − v1) +
// r3(v3 − v1) with (r2, r3) folded back into the triangle when r2 + r3 > 1. Point i draws its
// three numbers from (seed, i) alone.
std::vector<EntryPoint> sampleEntryPoints(const std::vector<atlas::AtlasTriangle>& triangles,
                                          int count, std::uint32_t seed);

// The cluster of every entry point: an object-median kd-tree, each node split across the longest
// side of its points' bounding box so that its two halves hold as many points as clusters they
// get (⌊k/2⌋ and ⌈k/2⌉ of its k clusters). Clusters come out equally large to within one point.
// Requires 1 ≤ clusters ≤ points.size().
std::vector<int> clusterEntryPoints(const std::vector<EntryPoint>& points, int clusters);

// K-means (the book's alternative): Lloyd's iterations from the kd-tree's clusters, in the space
// of position and normal, |Δp|² + (s·|Δn|)² with s a tenth of the points' bounding-box diagonal,
// so that points on differently facing surfaces (either side of a corner) part. Each iteration
// assigns every point to its nearest centroid (ties to the lower index) and moves the centroids
// to their members' means; a cluster that loses every member keeps its centroid. The sum of
// squared distances never grows. Deterministic.
std::vector<int> clusterEntryPointsKMeans(const std::vector<EntryPoint>& points, int clusters,
                                          int iterations);

// The sum over points of the squared distance (the metric above) to their cluster's mean: what
// K-means lowers.
double clusteringCost(const std::vector<EntryPoint>& points, const std::vector<int>& cluster_of,
                      int clusters);

// A visited point of a random walk as a virtual spot light with intensity
// I(θ) = intensity · cos θ about `normal` (the book's S·Π f/𝓛(f) · f · cos θ, times the share of
// its entry point's paths it stands for).
struct VirtualLight {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f};
  glm::vec3 intensity{0.0f};
  int cluster = 0;
};

struct LightWalks {
  std::vector<VirtualLight> lights;  // sorted by cluster, then entry point, then path
  // The visited points the book counts ("about 24 000 virtual light sources" for 4096 entry
  // points and two paths): every path's points, its entry point included, while `lights` holds
  // an entry point once (the same light for all its paths, with their weights summed).
  std::int64_t path_vertices = 0;
};

// `paths_per_entry` random walks from each entry point: cosine-distributed directions, and at
// each visited point (the entry point too) the walk goes on with probability 𝓛(albedo), the
// Rec.709 luminance of the diffuse reflectance (Russian roulette), so that the throughput changes
// by albedo/𝓛(albedo) per bounce. A walk ends when it leaves the scene or hits a back face (the
// atlas has one side per surface), or, when `max_vertices` > 0, at that many visited points (1:
// the entry point alone, the first indirect bounce). `total_area` is S. Path (i, j) draws from
// (seed, i, j) alone.
LightWalks traceLightWalks(const scene::RayCaster& caster, const scene::Scene& scene,
                           const std::vector<atlas::AtlasTriangle>& triangles,
                           const std::vector<EntryPoint>& entries,
                           const std::vector<int>& cluster_of_entry, int paths_per_entry,
                           double total_area, std::uint32_t seed, int max_vertices = 0);

}  // namespace gib::rt::lpm
