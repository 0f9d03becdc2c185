// The rays `gibench raycast-bench` casts (book §5.5.3: the speed of GPU ray casting "depends on
// the coherence of rays"): primary rays through the camera's pixel centres, the mirror reflections
// of those rays at their first hits (coherent secondary rays: neighbours stay neighbours), and
// cosine-distributed diffuse rays from the same points (incoherent ones). Secondary rays leave
// only where a primary ray hit something, so their sets are smaller than width × height.
#pragma once

#include "scene/ray_caster.h"
#include "scene/scene.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace gib::rt {

enum class RayKind { kPrimary, kReflection, kDiffuse };

// "primary", "reflection", "diffuse"; parse throws gib::InputError naming the choices.
std::string_view rayKindName(RayKind kind);
RayKind parseRayKind(std::string_view name);
const std::vector<std::string>& rayKindNames();

// World-space rays of one kind for a width × height image of the scene's camera; `caster` finds
// the primary hits secondary rays leave from (Embree, lent by the caller); `seed` picks the
// diffuse directions (a pure function of seed and pixel: the set does not depend on threads).
std::vector<scene::Ray> makeRaySet(const scene::Scene& scene, RayKind kind, int width, int height,
                                   std::uint64_t seed, const scene::RayCaster& caster);

}  // namespace gib::rt
