// Whether triangle meshes enclose a volume, for the tests of scenes whose light must not escape
// (the room) and of glass, which must be closed and face outwards (docs/architecture.md,
// "Materials"; scene/scene.h, Material).
#pragma once

#include "scene/scene.h"

#include <cstddef>
#include <vector>

namespace gib::test {

// The directed edges (a, b) of the meshes' triangles, compared by their end points' positions, so
// that meshes meeting at shared corners (a room's walls) count as one surface, that do not occur
// exactly once with their reverse (b, a) exactly once: 0 when the triangles form closed
// surfaces, every edge between exactly two triangles, wound consistently.
std::size_t unmatchedEdges(const std::vector<const scene::Mesh*>& meshes);

// The signed volume the triangles enclose, Σ a · (b × c) / 6: positive when a closed surface's
// triangles face outwards, negative when they face inwards.
double signedVolume(const std::vector<const scene::Mesh*>& meshes);

}  // namespace gib::test
