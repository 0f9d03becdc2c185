#include "scene/mesh_builder.h"
#include "support/mesh_topology.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
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

TEST(MeshBuilder, TorusIsClosedOutwardAndSmoothWithTheExactNormals) {
  // A torus about a slanted axis, so that the frame the builder makes is not the world's.
  const glm::vec3 centre(1.0f, 2.0f, 3.0f), axis(0.3f, 1.0f, -0.5f);
  const float major = 0.35f, minor = 0.15f;
  Mesh mesh;
  appendTorus(mesh, centre, axis, major, minor, 32, 12);
  EXPECT_EQ(mesh.positions.size(), 32u * 12u);
  EXPECT_EQ(mesh.triangles.size(), 2u * 32u * 12u);
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  EXPECT_EQ(test::unmatchedEdges({&mesh}), 0u) << "closed and consistently wound";
  // Outwards: the enclosed volume is positive and near the torus's 2π²Rr²; the 12-sided tube
  // keeps (12/2π)·sin(2π/12) ≈ 0.955 of the circle's area.
  const float pi = glm::pi<float>();
  const double exact = 2.0 * pi * pi * major * minor * minor;
  EXPECT_GT(test::signedVolume({&mesh}), 0.9 * exact);
  EXPECT_LT(test::signedVolume({&mesh}), exact);
  // Each vertex lies on the tube, minor from the circle of major radius about the axis, and its
  // normal is the unit vector from the circle's nearest point to it.
  const glm::vec3 a = glm::normalize(axis);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3 d = mesh.positions[i] - centre;
    const glm::vec3 radial = glm::normalize(d - glm::dot(d, a) * a);
    const glm::vec3 from_circle = mesh.positions[i] - (centre + major * radial);
    EXPECT_NEAR(glm::length(from_circle), minor, 1e-5f) << "vertex " << i;
    EXPECT_NEAR(glm::length(mesh.normals[i]), 1.0f, kUnitTolerance);
    EXPECT_LT(glm::length(mesh.normals[i] - from_circle / minor), 1e-4f) << "vertex " << i;
  }
  // Each normal points to its triangles' front side.
  for (const glm::uvec3& t : mesh.triangles) {
    const glm::vec3 face = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                                      mesh.positions[t[2]] - mesh.positions[t[0]]);
    for (int k = 0; k < 3; ++k) EXPECT_GT(glm::dot(face, mesh.normals[t[k]]), 0.0f);
  }
  // A torus needs a normal per vertex, as a smooth sphere does.
  Mesh flat;
  appendQuad(flat, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});
  EXPECT_THROW(appendTorus(flat, centre, axis, major, minor, 8, 4), std::logic_error);
}

TEST(MeshBuilder, ParallelepipedIsClosedAndFacesOutwardsEitherHandedness) {
  const glm::vec3 u(0.5f, 0.0f, 0.2f), v(0.0f, 0.6f, 0.0f), w(-0.004f, 0.0f, 0.01f);
  for (const bool swapped : {false, true}) {
    Mesh mesh;
    appendParallelepiped(mesh, glm::vec3(1, 2, 3), swapped ? v : u, swapped ? u : v, w);
    EXPECT_EQ(mesh.positions.size(), 8u);
    EXPECT_EQ(mesh.triangles.size(), 12u);
    EXPECT_TRUE(mesh.normals.empty());
    EXPECT_EQ(test::unmatchedEdges({&mesh}), 0u);
    // Outwards: the volume is +8·|u · (v × w)|.
    EXPECT_NEAR(test::signedVolume({&mesh}), 8.0 * std::abs(glm::dot(u, glm::cross(v, w))), 1e-6);
  }
}

TEST(MeshBuilder, MeshOfMaterialAddsBothAndLinksThem) {
  Scene scene;
  scene.materials.resize(2);
  Material glass;
  glass.name = "glass";
  glass.type = MaterialType::kGlass;
  Mesh& mesh = addMeshOfMaterial(scene, "pane", glass);
  EXPECT_EQ(mesh.name, "pane");
  EXPECT_TRUE(mesh.triangles.empty());
  ASSERT_EQ(scene.materials.size(), 3u);
  EXPECT_EQ(mesh.material, 2u);
  EXPECT_EQ(scene.materials[2].name, "glass");
  EXPECT_EQ(&mesh, &scene.meshes.back());
}

}  // namespace
}  // namespace gib::scene
