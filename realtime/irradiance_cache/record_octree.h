// The classic irradiance cache's store (Ward 1988; course notes 001, "octrees"): records in a loose
// octree, each in the deepest node whose cube holds its position and is at least as large as its
// zone of influence, so that a lookup at P visits only the nodes whose cubes grown by half their
// size contain P. What the CPU cache interpolates with; the GPU splatting has no such structure.
#pragma once

#include "realtime/irradiance_cache/irradiance_cache_shared.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace gib::rt {

class RecordOctree {
 public:
  // The cube of the root holds [lo, hi]; records contribute where w > 1/accuracy.
  RecordOctree(const glm::vec3& lo, const glm::vec3& hi, float accuracy);

  void insert(const gpu::IrradianceRecord& record);
  // rgb: Σ w_k·E_k(P, n) over the records with w_k(P) > 1/a; w: Σ w_k. Zero where none.
  glm::vec4 lookup(const glm::vec3& p, const glm::vec3& n) const;

  std::size_t size() const { return records_.size(); }
  std::size_t nodeCount() const { return nodes_.size(); }
  const std::vector<gpu::IrradianceRecord>& records() const { return records_; }

 private:
  struct Node {
    glm::vec3 centre;
    float half;  // half the cube's side
    std::array<std::int32_t, 8> children;
    std::vector<std::uint32_t> records;
  };
  void lookup(std::int32_t node, const glm::vec3& p, const glm::vec3& n, glm::vec4& sum) const;

  float accuracy_;
  std::vector<Node> nodes_;
  std::vector<gpu::IrradianceRecord> records_;
};

}  // namespace gib::rt
