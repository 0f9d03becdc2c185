#include "reference/primary_agreement.h"

#include "reference/embree_scene.h"
#include "scene/camera.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <stdexcept>

namespace gib::ref {

namespace {

constexpr float kDistanceTolerance = 1e-3f;  // relative
constexpr float kNormalTolerance = 0.999f;   // cosine

bool samePrimarySurface(const scene::Scene& scene, const Hit& hit, const float* position,
                        const float* normal) {
  const bool raster_hit = position[3] >= 0;
  if (!raster_hit || !hit.valid()) return raster_hit == hit.valid();
  if (std::abs(position[3] - hit.t) > kDistanceTolerance * hit.t) return false;
  const scene::Mesh& mesh = scene.meshes[hit.mesh];
  if (normal[3] != float(mesh.material)) return false;
  const glm::uvec3 t = mesh.triangles[hit.triangle];
  const glm::vec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
  const glm::vec3 expected = glm::normalize(glm::cross(b - a, c - a));
  return glm::dot(expected, glm::vec3(normal[0], normal[1], normal[2])) >= kNormalTolerance;
}

}  // namespace

PrimaryAgreement comparePrimarySurfaces(const scene::Scene& scene, const image::Image& position,
                                        const image::Image& normal, glm::vec2 offset) {
  if (position.channels() != 4 || normal.channels() != 4 || position.width() != normal.width() ||
      position.height() != normal.height())
    throw std::invalid_argument("primary surfaces need two RGBA images of one size");
  const int width = position.width(), height = position.height();
  const EmbreeScene embree(scene);
  const scene::CameraFrame frame = scene::makeCameraFrame(scene.camera, width, height);
  PrimaryAgreement agreement;
  agreement.mask = image::Image(width, height, 1);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      // The reference's own ray: the same function and the same image point as its camera.
      const glm::vec3 direction =
          scene::cameraRayDirection(frame, width, height, float(x) + offset.x, float(y) + offset.y);
      const Hit hit = embree.intersect(frame.origin, direction);
      const bool agrees = samePrimarySurface(scene, hit, position.pixel(x, y), normal.pixel(x, y));
      ++agreement.pixels;
      agreement.hits += hit.valid();
      agreement.disagreements += !agrees;
      agreement.mask.pixel(x, y)[0] = agrees ? 0.0f : 1.0f;
    }
  return agreement;
}

}  // namespace gib::ref
