// The six faces of an axis-aligned box turned inwards (each quad's front side, by appendQuad's
// winding, faces the box's inside): the closed room that tests of occlusion and random walks
// enclose a point in.
#pragma once

#include <glm/vec3.hpp>

#include <array>

namespace gib::test {

// Corners of each face in appendQuad's order: floor (+y), ceiling (−y), x = low (+x),
// x = high (−x), z = low (+z), z = high (−z).
inline std::array<std::array<glm::vec3, 4>, 6> inwardBoxFaces(glm::vec3 lo, glm::vec3 hi) {
  return {{
      {{{lo.x, lo.y, lo.z}, {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, lo.y, lo.z}}},
      {{{lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}}},
      {{{lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {lo.x, hi.y, hi.z}, {lo.x, lo.y, hi.z}}},
      {{{hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, hi.y, lo.z}}},
      {{{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z}}},
      {{{lo.x, lo.y, hi.z}, {lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, lo.y, hi.z}}},
  }};
}

}  // namespace gib::test
