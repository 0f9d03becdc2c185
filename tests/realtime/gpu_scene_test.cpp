#include "realtime/gpu_scene/gpu_scene.h"

#include "realtime/gbuffer/gbuffer.h"
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/objects.h"
#include "realtime/gl/shader_library.h"
#include "scene/builtin_scenes.h"
#include "scene/camera.h"
#include "support/gl_test_context.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <string>
#include <vector>

namespace gib::rt {
namespace {

using test::GlTest;

// Window coordinates (GL: y up, pixel centres at +0.5) and NDC depth of a world point.
glm::vec3 toWindow(const CameraTransform& t, int width, int height, const glm::vec3& p) {
  const glm::vec4 clip = t.projection * t.view * glm::vec4(p, 1.0f);
  const glm::vec3 ndc = glm::vec3(clip) / clip.w;
  return {(ndc.x + 1.0f) * 0.5f * float(width), (ndc.y + 1.0f) * 0.5f * float(height), ndc.z};
}

TEST(CameraTransform, RasterisesEachPixelCentreOnItsCameraRay) {
  const scene::Scene cornell = scene::loadScene("cornell");
  const glm::vec3 lo(0.0f), hi(556.0f, 549.0f, 560.0f);
  for (const auto& [width, height] : {std::array{256, 256}, std::array{320, 200}}) {
    const CameraTransform t = cameraTransform(cornell.camera, width, height, lo, hi);
    const scene::CameraFrame frame = scene::makeCameraFrame(cornell.camera, width, height);
    const std::array<std::array<int, 2>, 6> pixels = {{{0, 0},
                                                       {width - 1, 0},
                                                       {0, height - 1},
                                                       {width - 1, height - 1},
                                                       {width / 2, height / 3},
                                                       {17, 101}}};
    for (const auto& [x, y] : pixels)
      for (const float distance : {900.0f, 1100.0f, 1350.0f}) {
        const glm::vec3 direction =
            scene::cameraRayDirection(frame, width, height, float(x) + 0.5f, float(y) + 0.5f);
        const glm::vec3 window = toWindow(t, width, height, frame.origin + distance * direction);
        EXPECT_NEAR(window.x, float(x) + 0.5f, 1e-3f) << width << "×" << height << " " << x;
        // Image row 0 is GL's top row: readPixels flips the rows.
        EXPECT_NEAR(window.y, float(height - y) - 0.5f, 1e-3f)
            << width << "×" << height << " " << y;
        EXPECT_GT(window.z, -1.0f);  // between the clip planes
        EXPECT_LT(window.z, 1.0f);
      }
  }
}

TEST(CameraTransform, ClipPlanesHugTheBoundsOfASceneInFrontOfTheCamera) {
  // The Cornell box is 800 mm in front of the camera and at most ~1.42 m away: a near plane close
  // to it keeps the depth buffer's precision where the surfaces are.
  const scene::Scene cornell = scene::loadScene("cornell");
  const CameraTransform t =
      cameraTransform(cornell.camera, 256, 256, glm::vec3(0.0f), glm::vec3(556, 549, 560));
  EXPECT_GT(t.near_plane, 600.0f);
  EXPECT_LE(t.near_plane, 800.0f);
  EXPECT_GE(t.far_plane, glm::length(glm::vec3(278, 276, 1360)));
  EXPECT_LT(t.far_plane, 1500.0f);
}

TEST(CameraTransform, ACameraInsideItsSceneGetsANearPlaneAboveZero) {
  const scene::Scene chamber = scene::loadScene("chamber");
  const glm::vec3 lo = chamber.camera.position - 10.0f, hi = chamber.camera.position + 10.0f;
  const CameraTransform t = cameraTransform(chamber.camera, 256, 192, lo, hi);
  EXPECT_GT(t.near_plane, 0.0f);
  EXPECT_LT(t.near_plane, 0.01f);
  EXPECT_GT(t.far_plane, glm::length(hi - lo) * 0.5f);
}

TEST_F(GlTest, CornellEmittersAreTheCeilingLightFacingDown) {
  const scene::Scene cornell = scene::loadScene("cornell");
  const GpuScene gpu(cornell, 256, 256);
  ASSERT_EQ(gpu.emitters().size(), 2u);
  float area = 0;
  for (const EmitterTriangle& e : gpu.emitters()) {
    area += e.area;
    EXPECT_NEAR(e.normal.y, -1.0f, 1e-6f);
    EXPECT_GT(scene::luminance(e.emission), 0.0f);
  }
  EXPECT_NEAR(area, 130.0f * 105.0f, 1e-3f * 130.0f * 105.0f);
}

TEST_F(GlTest, EveryTriangleBecomesThreeVertices) {
  for (const char* name : {"cornell", "chamber"}) {
    const scene::Scene s = scene::loadScene(name);
    const GpuScene gpu(s, 64, 48);
    EXPECT_EQ(gpu.vertexCount(), 3 * s.triangleCount()) << name;
    for (const scene::Mesh& mesh : s.meshes)
      for (const glm::vec3& p : mesh.positions) {
        EXPECT_TRUE(glm::all(glm::lessThanEqual(gpu.boundsMin(), p))) << name;
        EXPECT_TRUE(glm::all(glm::lessThanEqual(p, gpu.boundsMax()))) << name;
      }
  }
}

TEST_F(GlTest, ASceneWithoutMeshesUploadsAndDrawsNothing) {
  const scene::Scene cloud = scene::loadScene("cloud");
  ASSERT_TRUE(cloud.meshes.empty());
  const GpuScene gpu(cloud, 64, 48);
  EXPECT_EQ(gpu.vertexCount(), 0u);
  EXPECT_TRUE(gpu.emitters().empty());
  for (const scene::MediumParticle& particle : cloud.medium.particles)
    EXPECT_TRUE(glm::all(glm::lessThanEqual(gpu.boundsMin(), particle.centre)));
  EXPECT_LT(gpu.camera().near_plane, gpu.camera().far_plane);

  GBuffer gbuffer(64, 48);
  gbuffer.render(gpu);
  const image::Image normal = gl::readTexture(gbuffer.normal(), 4);
  for (int y = 0; y < normal.height(); ++y)
    for (int x = 0; x < normal.width(); ++x) ASSERT_EQ(normal.pixel(x, y)[3], -1.0f);
}

// Every material of a scene reads back through scene.glsl's accessors (the materials buffer as a
// buffer texture, kMaterialTexels texels per record) with the scene's values, field by field.
TEST_F(GlTest, MaterialAccessorsReadEachMaterialsOwnFields) {
  const scene::Scene cornell = scene::loadScene("cornell");
  ASSERT_GE(cornell.materials.size(), 3u);
  const GpuScene gpu(cornell, 64, 48);
  const std::string source =
      "#include \"realtime/gpu_scene/scene.glsl\"\n"
      "layout(local_size_x = 1) in;\n"
      "layout(std430, binding = kTestFirstStorageBinding) buffer Out { vec4 o[]; };\n"
      "void main() {\n"
      "  uint m = gl_WorkGroupID.x;\n"
      "  o[3u * m] = vec4(materialDiffuse(m), materialIsPhong(m) ? 1.0 : 0.0);\n"
      "  o[3u * m + 1u] = vec4(materialSpecular(m), materialExponent(m));\n"
      "  o[3u * m + 2u] = vec4(materialEmission(m), 0.0);\n"
      "}\n";
  const gl::Program program = gl::buildProgram(
      {{GL_COMPUTE_SHADER, "test/materials.comp.glsl"}}, "",
      [&](std::string_view path) -> std::string_view {
        return path == "test/materials.comp.glsl" ? std::string_view(source) : gl::glslFile(path);
      });
  std::vector<glm::vec4> out(3 * cornell.materials.size(), glm::vec4(-7.0f));
  const gl::Buffer buffer = gl::Buffer::fromVector(out);
  buffer.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kTestFirstStorageBinding);
  gpu.bindSceneBuffers();
  program.use();
  glDispatchCompute(GLuint(cornell.materials.size()), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(buffer.id(), 0, GLsizeiptr(out.size() * sizeof(glm::vec4)), out.data());
  for (std::size_t m = 0; m < cornell.materials.size(); ++m) {
    const scene::Material& material = cornell.materials[m];
    const bool phong = material.type == scene::MaterialType::kPhong;
    EXPECT_EQ(out[3 * m], glm::vec4(material.diffuse, phong ? 1.0f : 0.0f)) << material.name;
    if (phong) {
      EXPECT_EQ(out[3 * m + 1], glm::vec4(material.specular, material.exponent)) << material.name;
    }
    EXPECT_EQ(glm::vec3(out[3 * m + 2]), material.emission) << material.name;
  }
}

// scene.glsl takes its bindings from gpu_scene_shared.h: the program the driver built must report
// the C++ values, so the shared header reaches GLSL intact.
TEST_F(GlTest, SceneGlslBindingsAreTheCppOnes) {
  const gl::Program program =
      gl::buildProgram({{GL_VERTEX_SHADER, "realtime/gbuffer/gbuffer.vert.glsl"},
                        {GL_FRAGMENT_SHADER, "realtime/gbuffer/gbuffer.frag.glsl"}});
  auto binding = [&](GLenum interface, const char* block) {
    const GLuint index = glGetProgramResourceIndex(program.id(), interface, block);
    EXPECT_NE(index, GL_INVALID_INDEX) << block;
    const GLenum property = GL_BUFFER_BINDING;
    GLint value = -1;
    glGetProgramResourceiv(program.id(), interface, index, 1, &property, 1, nullptr, &value);
    return GLuint(value);
  };
  GLint materials_unit = -1;
  glGetUniformiv(program.id(), program.uniform("u_materials"), &materials_unit);
  EXPECT_EQ(materials_unit, gpu::kMaterialsUnit);
  EXPECT_EQ(binding(GL_UNIFORM_BLOCK, "CameraBlock"), GLuint(gpu::kCameraBinding));
}

}  // namespace
}  // namespace gib::rt
