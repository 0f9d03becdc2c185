#include "scene/mesh_builder.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <stdexcept>

namespace gib::scene {
namespace {

// Float rounding of a unit vector built from sines and cosines, and of positions of size ~r.
constexpr float kUnitTolerance = 1e-6f;

TEST(MeshBuilder, SmoothSphereNormalsAreTheExactSphereNormals) {
  const glm::vec3 centre(380.0f, 100.0f, 380.0f);
  const float radius = 100.0f;
  for (bool inward : {false, true}) {
    Mesh mesh;
    appendSphere(mesh, centre, radius, 8, 16, inward, SphereShading::kSmooth);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      const glm::vec3 expected = (mesh.positions[i] - centre) / radius * (inward ? -1.0f : 1.0f);
      const glm::vec3& n = mesh.normals[i];
      EXPECT_NEAR(glm::length(n), 1.0f, kUnitTolerance);
      EXPECT_LT(glm::length(n - expected), 1e-5f) << "vertex " << i;
    }
    // Each normal points to its triangles' front side, the side their winding faces.
    for (const glm::uvec3& t : mesh.triangles) {
      const glm::vec3 face = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                                        mesh.positions[t[2]] - mesh.positions[t[0]]);
      for (int k = 0; k < 3; ++k) EXPECT_GT(glm::dot(face, mesh.normals[t[k]]), 0.0f);
    }
  }
}

TEST(MeshBuilder, SmoothAndFlatSpheresShareTheirGeometry) {
  Mesh flat, smooth;
  appendSphere(flat, glm::vec3(1, 2, 3), 0.5f, 16, 32, /*inward=*/true);
  appendSphere(smooth, glm::vec3(1, 2, 3), 0.5f, 16, 32, /*inward=*/true, SphereShading::kSmooth);
  EXPECT_TRUE(flat.normals.empty());
  EXPECT_EQ(flat.positions, smooth.positions);
  EXPECT_EQ(flat.triangles, smooth.triangles);
}

TEST(MeshBuilder, NormalsAndFlatPartsDoNotMix) {
  Mesh mesh;
  appendQuad(mesh, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});
  EXPECT_THROW(appendSphere(mesh, glm::vec3(0), 1.0f, 4, 8, false, SphereShading::kSmooth),
               std::logic_error);
  Mesh smooth;
  appendSphere(smooth, glm::vec3(0), 1.0f, 4, 8, false, SphereShading::kSmooth);
  EXPECT_THROW(appendSphere(smooth, glm::vec3(3), 1.0f, 4, 8, false), std::logic_error);
  // Two smooth spheres in one mesh keep one normal per vertex.
  appendSphere(smooth, glm::vec3(3), 1.0f, 4, 8, false, SphereShading::kSmooth);
  EXPECT_EQ(smooth.normals.size(), smooth.positions.size());
}

}  // namespace
}  // namespace gib::scene
