#include "support/form_factor.h"

#include "scene/mesh_builder.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gib::test {

double pointToPolygonFormFactor(const glm::dvec3& x, const glm::dvec3& n,
                                const std::vector<glm::dvec3>& polygon) {
  double sum = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec3 a = glm::normalize(polygon[i] - x);
    const glm::dvec3 b = glm::normalize(polygon[(i + 1) % polygon.size()] - x);
    const double angle = std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
    sum += angle * glm::dot(n, glm::normalize(glm::cross(a, b)));
  }
  return std::abs(sum) / (2 * std::numbers::pi);
}

scene::Scene facingUnitSquares(const scene::Material& top, const scene::Material& bottom) {
  scene::Scene s;
  s.name = "facing_unit_squares";
  s.camera.position = {0.5f, 0.5f, -3.0f};
  s.camera.look_at = {0.5f, 0.5f, 0.5f};
  s.materials = {top, bottom};
  scene::Mesh top_mesh, bottom_mesh;
  top_mesh.material = 0;
  bottom_mesh.material = 1;
  scene::appendQuad(top_mesh, {0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1});     // normal −y
  scene::appendQuad(bottom_mesh, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0});  // normal +y
  s.meshes = {top_mesh, bottom_mesh};
  return s;
}

const std::vector<glm::dvec3>& unitPatchCorners() {
  static const std::vector<glm::dvec3> corners = {
      {-0.5, 1, -0.5}, {0.5, 1, -0.5}, {0.5, 1, 0.5}, {-0.5, 1, 0.5}};
  return corners;
}

scene::Scene withUnitPatch(scene::Scene scene) {
  scene::Mesh square;
  square.name = "patch";
  const std::vector<glm::dvec3>& c = unitPatchCorners();
  scene::appendQuad(square, glm::vec3(c[0]), glm::vec3(c[1]), glm::vec3(c[2]), glm::vec3(c[3]));
  scene.meshes.push_back(square);
  return scene;
}

}  // namespace gib::test
