#include "scene/ray_caster.h"

#include <stdexcept>

namespace gib::scene {

void RayCaster::intersect(std::span<const Ray> rays, std::span<RayHit> hits,
                          bool /*coherent*/) const {
  if (hits.size() != rays.size()) throw std::invalid_argument("one hit per ray");
  for (std::size_t i = 0; i < rays.size(); ++i) {
    hits[i] = intersect(rays[i].origin, rays[i].direction, rays[i].t_near);
    if (hits[i].t >= rays[i].t_far) hits[i] = RayHit{};
  }
}

void RayCaster::occluded(std::span<const Ray> rays, std::span<std::uint8_t> blocked) const {
  if (blocked.size() != rays.size()) throw std::invalid_argument("one answer per ray");
  for (std::size_t i = 0; i < rays.size(); ++i)
    blocked[i] = intersect(rays[i].origin, rays[i].direction, rays[i].t_near).t < rays[i].t_far;
}

}  // namespace gib::scene
