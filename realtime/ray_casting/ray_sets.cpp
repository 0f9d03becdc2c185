#include "realtime/ray_casting/ray_sets.h"

#include "common/input_error.h"
#include "common/splitmix.h"
#include "scene/camera.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace gib::rt {

const std::vector<std::string>& rayKindNames() {
  static const std::vector<std::string> names = {"primary", "reflection", "diffuse"};
  return names;
}

std::string_view rayKindName(RayKind kind) {
  return rayKindNames()[std::size_t(kind)];
}

RayKind parseRayKind(std::string_view name) {
  for (std::size_t i = 0; i < rayKindNames().size(); ++i)
    if (rayKindNames()[i] == name) return RayKind(i);
  throw InputError(fmt::format("--rays '{}' is not a kind of rays; give one of {}", name,
                               fmt::join(rayKindNames(), ", ")));
}

namespace {

// A uniform number in [0, 1) from 64 random bits (the top 24, exactly representable).
float unitFloat(std::uint64_t bits) {
  return float(bits >> 40) * (1.0f / 16777216.0f);
}

// A cosine-distributed direction about unit n (Malley's method: a uniform disc point lifted).
glm::vec3 cosineDirection(const glm::vec3& n, float u1, float u2) {
  const float r = std::sqrt(u1), phi = 2.0f * std::numbers::pi_v<float> * u2;
  const glm::vec3 helper = std::abs(n.x) > 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 tangent = glm::normalize(glm::cross(helper, n));
  const glm::vec3 bitangent = glm::cross(n, tangent);
  return r * std::cos(phi) * tangent + r * std::sin(phi) * bitangent +
         std::sqrt(std::max(0.0f, 1.0f - u1)) * n;
}

}  // namespace

std::vector<scene::Ray> makeRaySet(const scene::Scene& scene, RayKind kind, int width, int height,
                                   std::uint64_t seed, const scene::RayCaster& caster) {
  const scene::CameraFrame frame = scene::makeCameraFrame(scene.camera, width, height);
  std::vector<scene::Ray> primary(std::size_t(width) * std::size_t(height));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      scene::Ray& ray = primary[std::size_t(y) * std::size_t(width) + std::size_t(x)];
      ray.origin = frame.origin;
      ray.direction = scene::cameraRayDirection(frame, width, height, x + 0.5f, y + 0.5f);
    }
  if (kind == RayKind::kPrimary) return primary;

  std::vector<scene::RayHit> hits(primary.size());
  caster.intersect(primary, hits, true);
  const float epsilon = caster.rayEpsilon();
  std::vector<scene::Ray> secondary;
  secondary.reserve(primary.size());
  for (std::size_t i = 0; i < primary.size(); ++i) {
    if (!hits[i].valid()) continue;
    const scene::Mesh& mesh = scene.meshes[hits[i].mesh];
    const glm::uvec3& tri = mesh.triangles[hits[i].triangle];
    const glm::vec3 a = mesh.positions[tri.x], b = mesh.positions[tri.y], c = mesh.positions[tri.z];
    const glm::vec3 d = primary[i].direction;
    glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    if (glm::dot(n, d) > 0.0f) n = -n;  // the side the ray arrives on
    scene::Ray ray;
    // Off the surface along the normal, as the reference spawns rays (embree_scene.h).
    ray.origin = primary[i].origin + hits[i].t * d + epsilon * n;
    if (kind == RayKind::kReflection) {
      ray.direction = d - 2.0f * glm::dot(d, n) * n;
    } else {
      const std::uint64_t key = splitMix64(seed ^ splitMix64(std::uint64_t(i)));
      ray.direction = cosineDirection(n, unitFloat(key), unitFloat(splitMix64(key)));
    }
    secondary.push_back(ray);
  }
  return secondary;
}

}  // namespace gib::rt
