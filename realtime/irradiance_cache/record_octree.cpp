#include "realtime/irradiance_cache/record_octree.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace gib::rt {

namespace {
// Below this the cubes are smaller than any zone the placement allows; it bounds the depth.
constexpr int kMaxDepth = 20;
}  // namespace

RecordOctree::RecordOctree(const glm::vec3& lo, const glm::vec3& hi, float accuracy)
    : accuracy_(accuracy) {
  const glm::vec3 size = hi - lo;
  const float half = 0.5f * std::max({size.x, size.y, size.z, 1e-6f}) * 1.001f;
  Node root{0.5f * (lo + hi), half, {}, {}};
  root.children.fill(-1);
  nodes_.push_back(root);
}

void RecordOctree::insert(const gpu::IrradianceRecord& record) {
  const glm::vec3 p(record.position_radius);
  const float radius = accuracy_ * record.position_radius.w;
  std::int32_t node = 0;
  for (int depth = 0; depth < kMaxDepth; ++depth) {
    const Node& n = nodes_[std::size_t(node)];
    const float child_half = 0.5f * n.half;
    if (radius > child_half) break;  // a child's loose cube might not hold the zone
    const int octant =
        (p.x >= n.centre.x ? 1 : 0) | (p.y >= n.centre.y ? 2 : 0) | (p.z >= n.centre.z ? 4 : 0);
    std::int32_t child = n.children[std::size_t(octant)];
    if (child < 0) {
      const glm::vec3 sign((octant & 1) ? 1.0f : -1.0f, (octant & 2) ? 1.0f : -1.0f,
                           (octant & 4) ? 1.0f : -1.0f);
      Node made{n.centre + child_half * sign, child_half, {}, {}};
      made.children.fill(-1);
      child = std::int32_t(nodes_.size());
      nodes_[std::size_t(node)].children[std::size_t(octant)] = child;
      nodes_.push_back(std::move(made));
    }
    node = child;
  }
  nodes_[std::size_t(node)].records.push_back(std::uint32_t(records_.size()));
  records_.push_back(record);
}

glm::vec4 RecordOctree::lookup(const glm::vec3& p, const glm::vec3& n) const {
  glm::vec4 sum(0.0f);
  lookup(0, p, n, sum);
  return sum;
}

void RecordOctree::lookup(std::int32_t index, const glm::vec3& p, const glm::vec3& n,
                          glm::vec4& sum) const {
  const Node& node = nodes_[std::size_t(index)];
  // A record lies in its node's cube and its zone reaches at most half the side beyond it.
  const glm::vec3 d = glm::abs(p - node.centre);
  if (std::max({d.x, d.y, d.z}) > 2.0f * node.half && index != 0) return;
  for (std::uint32_t r : node.records) {
    const gpu::IrradianceRecord& record = records_[r];
    const float w = gpu::recordWeight(record, p, n);
    if (w <= 1.0f / accuracy_) continue;
    sum += glm::vec4(w * gpu::recordIrradiance(record, p, n), w);
  }
  for (std::int32_t child : node.children)
    if (child >= 0) lookup(child, p, n, sum);
}

}  // namespace gib::rt
