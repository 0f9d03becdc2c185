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

#include <algorithm>
#include <array>
#include <cmath>
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

// Cornell's materials and one of each specular kind (a metal, a perfect mirror, a tinted glass),
// so that every field of the record differs from its neighbours'.
scene::Scene sceneWithEveryMaterialType() {
  scene::Scene s = scene::loadScene("cornell");
  scene::Material gold;
  gold.name = "gold";
  gold.type = scene::MaterialType::kMirror;
  gold.conductor_n = scene::Rgb(0.18f, 0.42f, 1.37f);
  gold.conductor_k = scene::Rgb(3.42f, 2.35f, 1.77f);
  scene::Material perfect;
  perfect.name = "perfect mirror";
  perfect.type = scene::MaterialType::kMirror;
  perfect.perfect_mirror = true;
  scene::Material glass;
  glass.name = "tinted glass";
  glass.type = scene::MaterialType::kGlass;
  glass.ior = 1.33f;
  glass.absorption = scene::Rgb(0.01f, 0.02f, 0.03f);
  for (const scene::Material& m : {gold, perfect, glass}) s.materials.push_back(m);
  return s;
}

int expectedType(scene::MaterialType type) {
  switch (type) {
    case scene::MaterialType::kLambert:
      return gpu::kMaterialLambert;
    case scene::MaterialType::kPhong:
      return gpu::kMaterialPhong;
    case scene::MaterialType::kMirror:
      return gpu::kMaterialMirror;
    case scene::MaterialType::kGlass:
      return gpu::kMaterialGlass;
  }
  return -1;
}

// Every material of a scene reads back through scene.glsl's accessors (the materials buffer as a
// buffer texture, kMaterialTexels texels per record) with the scene's values, field by field.
TEST_F(GlTest, MaterialAccessorsReadEachMaterialsOwnFields) {
  const scene::Scene s = sceneWithEveryMaterialType();
  const GpuScene gpu(s, 64, 48);
  constexpr int kOut = 6;  // vec4s written per material below
  const std::string source =
      "#include \"realtime/gpu_scene/scene.glsl\"\n"
      "layout(local_size_x = 1) in;\n"
      "layout(std430, binding = kTestFirstStorageBinding) buffer Out { vec4 o[]; };\n"
      "void main() {\n"
      "  uint m = gl_WorkGroupID.x, i = 6u * m;\n"
      "  o[i] = vec4(materialDiffuse(m), float(materialType(m)));\n"
      "  o[i + 1u] = vec4(materialSpecular(m), materialExponent(m));\n"
      "  o[i + 2u] = vec4(materialEmission(m), materialIsPhong(m) ? 1.0 : 0.0);\n"
      "  o[i + 3u] = vec4(materialConductorN(m), materialIsPerfectMirror(m) ? 1.0 : 0.0);\n"
      "  o[i + 4u] = vec4(materialConductorK(m), 0.0);\n"
      "  o[i + 5u] = vec4(materialAbsorption(m), materialIor(m));\n"
      "}\n";
  const gl::Program program = gl::buildProgram(
      {{GL_COMPUTE_SHADER, "test/materials.comp.glsl"}}, "",
      [&](std::string_view path) -> std::string_view {
        return path == "test/materials.comp.glsl" ? std::string_view(source) : gl::glslFile(path);
      });
  std::vector<glm::vec4> out(kOut * s.materials.size(), glm::vec4(-7.0f));
  const gl::Buffer buffer = gl::Buffer::fromVector(out);
  buffer.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kTestFirstStorageBinding);
  gpu.bindSceneBuffers();
  program.use();
  glDispatchCompute(GLuint(s.materials.size()), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(buffer.id(), 0, GLsizeiptr(out.size() * sizeof(glm::vec4)), out.data());
  for (std::size_t m = 0; m < s.materials.size(); ++m) {
    const scene::Material& material = s.materials[m];
    const glm::vec4* o = &out[kOut * m];
    const bool phong = material.type == scene::MaterialType::kPhong;
    EXPECT_EQ(o[0], glm::vec4(material.diffuse, float(expectedType(material.type))))
        << material.name;
    EXPECT_EQ(o[1], glm::vec4(material.specular, material.exponent)) << material.name;
    EXPECT_EQ(o[2], glm::vec4(material.emission, phong ? 1.0f : 0.0f)) << material.name;
    EXPECT_EQ(o[3], glm::vec4(material.conductor_n, material.perfect_mirror ? 1.0f : 0.0f))
        << material.name;
    EXPECT_EQ(o[4], glm::vec4(material.conductor_k, 0.0f)) << material.name;
    EXPECT_EQ(o[5], glm::vec4(material.absorption, material.ior)) << material.name;
  }
}

// What the vertex shader reads at every vertex of GpuScene::draw (vertex.glsl), in draw order.
struct FetchedVertex {
  glm::vec4 position, normal, shading_normal;  // w of normal: the material
};

std::vector<FetchedVertex> fetchVertices(const GpuScene& gpu) {
  const std::string source =
      "#include \"realtime/gpu_scene/vertex.glsl\"\n"
      "struct FetchedVertex { vec4 position, normal, shading_normal; };\n"
      "layout(std430, binding = kTestFirstStorageBinding) buffer Out { FetchedVertex o[]; };\n"
      "void main() {\n"
      "  o[gl_VertexID] = FetchedVertex(vec4(vertex_position, 0.0),\n"
      "      vec4(vertex_normal, float(vertex_material)), vec4(vertex_shading_normal, 0.0));\n"
      "  gl_Position = vec4(0.0);\n"
      "}\n";
  const gl::Program program = gl::buildProgram(
      {{GL_VERTEX_SHADER, "test/fetch.vert.glsl"}}, "",
      [&](std::string_view path) -> std::string_view {
        return path == "test/fetch.vert.glsl" ? std::string_view(source) : gl::glslFile(path);
      });
  std::vector<FetchedVertex> out(gpu.vertexCount(),
                                 {glm::vec4(-7.0f), glm::vec4(-7.0f), glm::vec4(-7.0f)});
  const gl::Buffer buffer = gl::Buffer::fromVector(out);
  buffer.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kTestFirstStorageBinding);
  // A draw needs a complete framebuffer even when nothing reaches it: one without attachments.
  const gl::Framebuffer framebuffer;
  glNamedFramebufferParameteri(framebuffer.id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, 1);
  glNamedFramebufferParameteri(framebuffer.id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, 1);
  framebuffer.bind();
  program.use();
  glEnable(GL_RASTERIZER_DISCARD);
  gpu.draw();
  glDisable(GL_RASTERIZER_DISCARD);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(buffer.id(), 0, GLsizeiptr(out.size() * sizeof(FetchedVertex)),
                          out.data());
  return out;
}

// Each mesh's vertices as the vertex shader must see them: the geometric normal exactly as GpuScene
// computed it before shading normals existed ((b − a) × (c − a), normalised in float), the
// material, and the mesh's own normal or zero.
void expectVerticesOf(const scene::Scene& s, const std::vector<FetchedVertex>& fetched) {
  ASSERT_EQ(fetched.size(), 3 * s.triangleCount());
  std::size_t i = 0;
  for (const scene::Mesh& mesh : s.meshes)
    for (const glm::uvec3& t : mesh.triangles) {
      const glm::vec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
      const glm::vec3 cross = glm::cross(b - a, c - a);
      const glm::vec3 normal = cross / glm::length(cross);
      for (int k = 0; k < 3; ++k, ++i) {
        const glm::vec3 shading = mesh.normals.empty() ? glm::vec3(0.0f) : mesh.normals[t[k]];
        ASSERT_EQ(fetched[i].position, glm::vec4(mesh.positions[t[k]], 0.0f)) << mesh.name << i;
        ASSERT_EQ(fetched[i].normal, glm::vec4(normal, float(mesh.material))) << mesh.name << i;
        ASSERT_EQ(fetched[i].shading_normal, glm::vec4(shading, 0.0f)) << mesh.name << i;
      }
    }
}

// The back wall of the Cornell box with shading normals that lean towards its corners, so that
// they differ from vertex to vertex and from the geometric normal (0, 0, −1).
scene::Scene cornellWithSmoothBackWall() {
  scene::Scene s = scene::loadScene("cornell");
  for (scene::Mesh& mesh : s.meshes) {
    if (mesh.name != "back_wall") continue;
    const glm::vec3 centre(278.0f, 274.0f, 559.2f);
    for (const glm::vec3& p : mesh.positions)
      mesh.normals.push_back(glm::normalize(glm::vec3(0, 0, -1) + (p - centre) / 600.0f));
  }
  scene::validateScene(s);
  return s;
}

TEST_F(GlTest, FlatMeshesKeepTheirVerticesAndSmoothOnesAddTheirNormals) {
  const scene::Scene cornell = scene::loadScene("cornell");
  expectVerticesOf(cornell, fetchVertices(GpuScene(cornell, 64, 48)));
  const scene::Scene smooth = cornellWithSmoothBackWall();
  expectVerticesOf(smooth, fetchVertices(GpuScene(smooth, 64, 48)));
}

// The G-buffer interpolates a smooth mesh's normals across its triangles and keeps every flat
// mesh's geometric normal bit for bit, whether or not the scene also has smooth meshes.
TEST_F(GlTest, GBufferInterpolatesShadingNormalsOfSmoothMeshesOnly) {
  const scene::Scene flat = scene::loadScene("cornell");
  const scene::Scene smooth = cornellWithSmoothBackWall();
  const scene::Mesh& wall =
      *std::find_if(smooth.meshes.begin(), smooth.meshes.end(),
                    [](const scene::Mesh& m) { return m.name == "back_wall"; });
  constexpr int kSize = 64;
  auto gbufferImages = [&](const scene::Scene& s) {
    const GpuScene gpu(s, kSize, kSize);
    GBuffer gbuffer(kSize, kSize);
    gbuffer.render(gpu);
    return std::pair(gl::readTexture(gbuffer.position(), 4), gl::readTexture(gbuffer.normal(), 4));
  };
  const auto [flat_position, flat_normal] = gbufferImages(flat);
  const auto [position, normal] = gbufferImages(smooth);
  // Interpolation in float of positions and normals, then renormalisation: a few ulps of each.
  constexpr float kInterpolationTolerance = 1e-4f;
  int wall_pixels = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const float* p = position.pixel(x, y);
      const float* n = normal.pixel(x, y);
      const glm::vec3 flat_n(flat_normal.pixel(x, y)[0], flat_normal.pixel(x, y)[1],
                             flat_normal.pixel(x, y)[2]);
      ASSERT_EQ(p[3], flat_position.pixel(x, y)[3]) << x << "," << y;  // the same surfaces
      if (p[3] < 0 || std::abs(p[2] - 559.2f) > 0.5f) {
        for (int c = 0; c < 3; ++c) ASSERT_EQ(n[c], flat_n[c]) << x << "," << y;
        continue;
      }
      // On the wall: the perspective-correct interpolation of its vertex normals at the pixel's
      // point, i.e. the wall's normal field evaluated at barycentric coordinates of that point.
      ++wall_pixels;
      const glm::vec3 point(p[0], p[1], p[2]);
      bool inside = false;
      for (const glm::uvec3& t : wall.triangles) {
        const glm::vec3 a = wall.positions[t.x], b = wall.positions[t.y], c = wall.positions[t.z];
        const glm::vec3 cross = glm::cross(b - a, c - a);
        const float area = glm::dot(cross, cross);
        const float wa = glm::dot(glm::cross(b - point, c - point), cross) / area;
        const float wb = glm::dot(glm::cross(c - point, a - point), cross) / area;
        const float wc = 1.0f - wa - wb;
        if (std::min({wa, wb, wc}) < -1e-3f) continue;
        inside = true;
        const glm::vec3 expected = glm::normalize(wa * wall.normals[t.x] + wb * wall.normals[t.y] +
                                                  wc * wall.normals[t.z]);
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(n[c], expected[c], kInterpolationTolerance) << x << "," << y;
        break;
      }
      EXPECT_TRUE(inside) << x << "," << y;
    }
  EXPECT_GT(wall_pixels, kSize * kSize / 8);
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
