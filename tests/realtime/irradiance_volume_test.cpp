// `irradiance_volume` on the GPU: probe views look where the SH tables assume, the GLSL basis
// and trilinear interpolation agree with the CPU and are exact at the probes, zero bounces is
// `direct`, and more bounces bring the Cornell box closer to full global illumination.
#include "realtime/techniques/irradiance_volume/irradiance_volume_technique.h"

#include "common/input_error.h"
#include "metrics/image_metrics.h"
#include "realtime/gl/shader_library.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/sh/spherical_harmonics.h"
#include "realtime/technique_runner.h"
#include "reference/progressive_renderer.h"
#include "scene/builtin_scenes.h"
#include "scene/camera.h"
#include "scene/mesh_builder.h"
#include "support/gl_test_context.h"
#include "support/technique_frame.h"
#include "support/test_materials.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>

namespace gib::rt {
namespace {

class IrradianceVolumeGl : public test::GlTest {};

TEST_F(IrradianceVolumeGl, ProbeViewsLookAlongTheCubeTexelDirections) {
  const scene::Scene scene = scene::loadScene("cornell");
  const GpuScene gpu_scene(scene, 32, 32);
  const ProbeGrid grid = makeProbeGrid(gpu_scene.boundsMin(), gpu_scene.boundsMax(), 2, 8, 1 << 20);
  GBuffer gbuffer(grid.atlasWidth(), grid.atlasHeight());
  gbuffer.renderViews(gpu_scene, grid.views(0.1f, 1e4f));
  const image::Image position = gl::readTexture(gbuffer.position(), 4);
  int hits = 0, checked = 0;
  for (int probe = 0; probe < grid.probeCount(); ++probe)
    for (int face = 0; face < 6; ++face)
      for (int j = 0; j < grid.face; ++j)
        for (int i = 0; i < grid.face; ++i) {
          ++checked;
          // readTexture puts the bottom row (j = 0 of a tile) last.
          const glm::ivec2 tile = grid.tileOrigin(probe, face);
          const float* p = position.pixel(tile.x + i, grid.atlasHeight() - 1 - (tile.y + j));
          if (p[3] <= 0) continue;
          ++hits;
          const glm::vec3 seen =
              glm::normalize(glm::vec3(p[0], p[1], p[2]) - grid.probePosition(probe));
          EXPECT_GT(glm::dot(seen, sh::cubeTexelDirection(face, i, j, grid.face)), 0.999f)
              << "probe " << probe << " face " << face << " texel " << i << "," << j;
        }
  // The Cornell box is closed but for its open front: most texels see a surface.
  EXPECT_GT(hits, checked * 3 / 4);
}

// A compute shader around irradiance_volume.glsl: the GLSL basis at given directions, and the
// interpolated coefficients at given points.
constexpr const char* kProbeShader = R"(
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/techniques/irradiance_volume/irradiance_volume.glsl"
layout(local_size_x = 1) in;
layout(std430, binding = kTestFirstStorageBinding) buffer Queries { vec4 queries[]; };
layout(std430, binding = kTestFirstStorageBinding + 1) buffer Results { vec4 results[]; };
uniform int u_basis;
void main() {
  int q = int(gl_WorkGroupID.x);
  if (u_basis == 1) {
    float y[kShMaxCoefficients];
    shBasis(normalize(queries[q].xyz), y);
    for (int i = 0; i < kShMaxCoefficients; ++i) results[q * kShMaxCoefficients + i] = vec4(y[i]);
  } else {
    vec3 L[kShMaxCoefficients];
    interpolateCoefficients(queries[q].xyz, L);
    for (int i = 0; i < kShMaxCoefficients; ++i) results[q * kShMaxCoefficients + i] = vec4(L[i], 0.0);
  }
}
)";

std::vector<glm::vec4> runProbeShader(const gl::Program& program,
                                      const std::vector<glm::vec4>& queries, bool basis) {
  const gl::Buffer query_buffer = gl::Buffer::fromVector(queries);
  std::vector<glm::vec4> results(queries.size() * sh::kShMaxCoefficients);
  const gl::Buffer result_buffer = gl::Buffer::fromVector(results);
  query_buffer.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kTestFirstStorageBinding);
  result_buffer.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kTestFirstStorageBinding + 1);
  program.use();
  program.set("u_basis", basis ? 1 : 0);
  glDispatchCompute(GLuint(queries.size()), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(result_buffer.id(), 0, GLsizeiptr(results.size() * sizeof(glm::vec4)),
                          results.data());
  return results;
}

TEST_F(IrradianceVolumeGl, GlslBasisAndInterpolationAgreeWithTheCpuAndAreExactAtProbes) {
  const gl::Program program = gl::buildProgram(
      {{GL_COMPUTE_SHADER, "test/probe.comp.glsl"}}, "#define SH_COEFFICIENT_COUNT 9\n",
      [](std::string_view path) -> std::string_view {
        return path == "test/probe.comp.glsl" ? std::string_view(kProbeShader) : gl::glslFile(path);
      });
  // The basis.
  const std::vector<glm::vec4> directions = {{0, 0, 1, 0}, {1, 2, -3, 0}, {-0.3f, 0.9f, 0.1f, 0}};
  const std::vector<glm::vec4> basis = runProbeShader(program, directions, true);
  for (std::size_t q = 0; q < directions.size(); ++q) {
    const auto expected = sh::evaluateBasis(glm::normalize(glm::vec3(directions[q])));
    for (int i = 0; i < sh::kShMaxCoefficients; ++i)
      EXPECT_NEAR(basis[q * sh::kShMaxCoefficients + std::size_t(i)].x, expected[std::size_t(i)],
                  1e-5)
          << q << " " << i;
  }
  // Interpolation: each probe's coefficients are distinct; at a probe they come back exactly,
  // halfway between two probes they are the mean.
  const ProbeGrid grid = makeProbeGrid({0, 0, 0}, {3, 3, 3}, 3, 4, 1 << 20);
  std::vector<glm::vec4> coefficients(std::size_t(grid.probeCount()) * sh::kShMaxCoefficients);
  for (std::size_t i = 0; i < coefficients.size(); ++i)
    coefficients[i] = glm::vec4(float(i), float(i % 7), -float(i % 5), 0);
  const gl::Buffer buffer = gl::Buffer::fromVector(coefficients);
  const gl::Texture texels = gl::Texture::makeBuffer(GL_RGBA32F, buffer);
  texels.bind(gpu::kProbeCoefficientsUnit);
  const gl::Buffer phong = gl::Buffer::fromVector(std::vector<float>(4, 0.0f));
  phong.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kPhongFactorsBinding);
  program.set("u_grid_n", grid.n);
  program.set("u_grid_origin", grid.origin);
  program.set("u_grid_cell", grid.cell);
  program.set("u_indirect_shadows", 0);
  std::vector<glm::vec4> points;
  for (int probe = 0; probe < grid.probeCount(); ++probe)
    points.push_back(glm::vec4(grid.probePosition(probe), 0));
  points.push_back(glm::vec4(0.5f * (grid.probePosition(0) + grid.probePosition(1)), 0));
  const std::vector<glm::vec4> interpolated = runProbeShader(program, points, false);
  for (int probe = 0; probe < grid.probeCount(); ++probe)
    for (int i = 0; i < 9; ++i) {
      const glm::vec4 got = interpolated[std::size_t(probe * sh::kShMaxCoefficients + i)];
      const glm::vec4 want = coefficients[std::size_t(gpu::probeCoefficientIndex(probe, i))];
      EXPECT_NEAR(got.x, want.x, 1e-3f * (1 + std::abs(want.x))) << probe << " " << i;
      EXPECT_NEAR(got.y, want.y, 1e-4f) << probe << " " << i;
    }
  const std::size_t mid = std::size_t(grid.probeCount()) * sh::kShMaxCoefficients;
  const std::size_t second = std::size_t(gpu::probeCoefficientIndex(1, 0));
  EXPECT_NEAR(interpolated[mid].x, 0.5f * (coefficients[0].x + coefficients[second].x), 1e-3f);
}

TechniqueRunSettings smallRun() {
  TechniqueRunSettings settings;
  settings.width = 48;
  settings.height = 48;
  settings.warmup_frames = 0;
  settings.frames = 1;
  settings.context.debug = true;  // any GL error fails the run
  return settings;
}

image::Image render(const scene::Scene& scene, const std::string& technique,
                    const std::vector<std::string>& set, scene::PathClass* path_class = nullptr) {
  const TechniqueInfo& info = findTechnique(technique);
  const TechniqueRunResult result =
      runTechnique(scene, info, parseParameters(info.parameters, set, technique), smallRun());
  if (path_class) *path_class = result.path_class;
  return result.image;
}

TEST(IrradianceVolume, ZeroBouncesIsTheDirectTechnique) {
  const scene::Scene scene = scene::loadScene("cornell");
  scene::PathClass path_class;
  const image::Image volume =
      render(scene, "irradiance_volume", {"bounces=0", "light_samples=4"}, &path_class);
  const image::Image direct = render(scene, "direct", {"light_samples=4"});
  EXPECT_EQ(path_class, (scene::PathClass{0, 1}));
  ASSERT_EQ(volume.data().size(), direct.data().size());
  for (std::size_t i = 0; i < volume.data().size(); ++i)
    ASSERT_NEAR(volume.data()[i], direct.data()[i], 1e-6f) << i;
}

TEST(IrradianceVolume, AMovingLightIsBackAtRestOnTheLastFrame) {
  // motion=light circles the light over the run; the measured image is the scene's own, the
  // same as with the light at rest (motion=objects moves nothing it draws).
  const scene::Scene scene = scene::loadScene("cornell");
  const TechniqueInfo& info = findTechnique("irradiance_volume");
  TechniqueRunSettings settings = smallRun();
  settings.warmup_frames = 2;
  settings.frames = 3;
  auto image = [&](const char* motion) {
    return runTechnique(scene, info,
                        parseParameters(info.parameters, {motion, "light_samples=4"}, "iv"),
                        settings)
        .image;
  };
  const image::Image moving = image("motion=light"), still = image("motion=objects");
  for (std::size_t i = 0; i < moving.data().size(); ++i)
    ASSERT_NEAR(moving.data()[i], still.data()[i], 1e-5f) << i;
}

TEST(IrradianceVolume, MoreBouncesComeCloserToFullGlobalIllumination) {
  // relMSE against the full reference (512 spp, whose own noise is far below the differences
  // measured here: 0.07, 0.02 and 0.01 at 128² on this scene) falls with every bounce.
  const scene::Scene scene = scene::loadScene("cornell");
  ref::RenderSettings settings;
  settings.width = settings.height = 48;
  settings.spp = 512;
  const image::Image reference = ref::renderReference(scene, settings).mean;
  double previous = 1e9;
  for (int bounces : {0, 1, 2}) {
    scene::PathClass path_class;
    const image::Image image =
        render(scene, "irradiance_volume",
               {"bounces=" + std::to_string(bounces), "light_samples=8"}, &path_class);
    EXPECT_EQ(path_class, (scene::PathClass{0, bounces + 1}));
    const double error = metrics::computeRelMse(reference, image, metrics::kRelativeEpsilon).value;
    EXPECT_LT(error, previous) << bounces << " bounces";
    previous = error;
  }
}

// The GPU commands of a frame with moving objects at the paper's settings (4³ probes, 16 light
// samples): the probes' 384 cube faces rasterised by instanced draws of
// gpu::kMaxGBufferViewsPerDraw views (24), the camera's G-buffer and emission, one shadow draw and
// a shading pass per view (camera, probes), the SH projection, the probes' relighting and the
// camera's indirect light (it was 393 with a draw per cube face).
TEST(IrradianceVolume, GpuCommandsPerFrameStayWithinTheirBound) {
  const scene::Scene scene = scene::loadScene("cornell");
  const TechniqueInfo& info = findTechnique("irradiance_volume");
  TechniqueRunSettings settings = smallRun();
  settings.frames = 2;
  const TechniqueRunResult result = runTechnique(
      scene, info, parseParameters(info.parameters, {"motion=objects"}, "iv"), settings);
  const PassRecord& frame = result.profile.passes.front();
  ASSERT_EQ(frame.gpu_commands.size(), 2u);
  EXPECT_EQ(frame.gpu_commands[0], frame.gpu_commands[1]) << "the same work every frame";
  EXPECT_LE(frame.gpu_commands[0], 33);
}

// A white sphere (albedo 0.8, r = 0.5) on a grey ground (0.5, 20 m square) under a constant
// environment map of radiance 1. The map's light reaches the surfaces through the direct light's
// samples, so the probes must not see it (their background texels stay black): the volume's
// indirect light is then light reflected by the ground and the sphere, the reference's paths of
// two bounces and more. Were the map in the probes too, every upward-facing surface would gain
// about albedo × 1 again (0.5 on the ground: double its direct light).
TEST(IrradianceVolume, AnEnvironmentMapLightsTheProbesOnlyThroughTheSurfaces) {
  constexpr int kSize = 48;
  constexpr glm::vec3 kCentre{0.0f, 0.5f, 0.0f};
  constexpr float kRadius = 0.5f, kGround = 10.0f;
  scene::Scene s;
  s.name = "sphere on ground under a constant map";
  scene::appendQuad(scene::addMeshOfMaterial(s, "ground", test::lambertMaterial(0.5f)),
                    {-kGround, 0, -kGround}, {-kGround, 0, kGround}, {kGround, 0, kGround},
                    {kGround, 0, -kGround});
  scene::appendSphere(scene::addMeshOfMaterial(s, "sphere", test::lambertMaterial(0.8f)), kCentre,
                      kRadius, 24, 48, /*inward=*/false, scene::SphereShading::kSmooth);
  std::vector<float> texels(std::size_t(2 * 4 * 4 * 3), 1.0f);
  s.environment = scene::makeEnvironmentMap(8, 4, std::move(texels), "constant");
  s.camera.position = {0.0f, 1.2f, 3.0f};
  s.camera.look_at = {0.0f, 0.3f, 0.0f};
  s.camera.vertical_fov_deg = 40.0f;

  const std::vector<std::string> direct_light = {"light_samples=64"};
  std::vector<std::string> volume_set = direct_light;
  volume_set.insert(volume_set.end(), {"bounces=1", "grid_bounds=objects", "grid=4"});
  const TechniqueRunResult volume = test::renderOneFrame(s, "irradiance_volume", volume_set, kSize);
  const TechniqueRunResult direct = test::renderOneFrame(s, "direct", direct_light, kSize);
  EXPECT_EQ(volume.path_class, (scene::PathClass{0, 2}));
  // The reference's indirect class: paths of two bounces and more, 256 spp through the pixel
  // centres (its noise, a few per cent of a pixel, averages out over the hundreds of pixels
  // summed below).
  const image::Image indirect_reference =
      test::renderCentreClassReference(s, kSize, 256,
                                       scene::PathClass{2, scene::PathClass::kUnlimited})
          .mean;

  // Mean indirect radiance (luminance-free: the scene is grey) over the sphere's pixels and over
  // the ground's, classified by the pixel centre's ray against the analytic sphere and plane.
  const scene::CameraFrame frame = scene::makeCameraFrame(s.camera, kSize, kSize);
  double sums[2][3] = {};  // [sphere, ground][volume − direct, reference, direct]
  int counts[2] = {0, 0};
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const glm::vec3 d = scene::cameraRayDirection(frame, kSize, kSize, x + 0.5f, y + 0.5f);
      const glm::vec3 oc = s.camera.position - kCentre;
      const float b = glm::dot(oc, d), c = glm::dot(oc, oc) - kRadius * kRadius;
      int which = -1;
      if (b * b - c > 0.01f)
        which = 0;  // clear of the silhouette, where facets differ
      else if (b * b - c < -0.05f && d.y < -0.05f)
        which = 1;
      if (which < 0) continue;
      const float v = volume.image.pixel(x, y)[1], dr = direct.image.pixel(x, y)[1];
      sums[which][0] += v - dr;
      sums[which][1] += indirect_reference.pixel(x, y)[1];
      sums[which][2] += dr;
      ++counts[which];
    }
  ASSERT_GT(counts[0], 100);
  ASSERT_GT(counts[1], 500);
  for (int which : {0, 1}) {
    const double volume_indirect = sums[which][0] / counts[which];
    const double reference_indirect = sums[which][1] / counts[which];
    const double direct_mean = sums[which][2] / counts[which];
    std::printf("%s: direct %.4f, indirect: volume %.4f, reference %.4f\n",
                which == 0 ? "sphere" : "ground", direct_mean, volume_indirect, reference_indirect);
    // The volume's indirect light within a tenth of the direct light of the reference's: a map
    // leaking into the probes would add some 0.3-0.5 here, a black ground take 0.1 from the sphere.
    EXPECT_NEAR(volume_indirect, reference_indirect, 0.1 * direct_mean)
        << (which == 0 ? "sphere" : "ground");
  }
}

TEST(IrradianceVolume, ObjectBoundsLeaveOutTheGround) {
  // outdoor's glossy sphere (r = 0.5 at (0, 0.5, 0)) on its 100 m ground: the grid spans the
  // sphere's box grown by its extent on each side, within the scene's bounds (y from 0 to 1), so
  // that a 4³ grid's inner probes stand just outside the sphere, not 25 m apart.
  const scene::Scene outdoor = scene::loadScene("outdoor", {"objects=glossy"});
  const ProbeBounds bounds = objectsProbeBounds(outdoor);
  for (int axis : {0, 2}) {
    EXPECT_NEAR(bounds.min[axis], -1.5f, 1e-3f);
    EXPECT_NEAR(bounds.max[axis], 1.5f, 1e-3f);
  }
  EXPECT_NEAR(bounds.min.y, 0.0f, 1e-6f);
  EXPECT_NEAR(bounds.max.y, 1.0f, 1e-3f);
  const ProbeGrid grid = makeProbeGrid(bounds.min, bounds.max, 4, 8, 1 << 20);
  for (int probe = 0; probe < grid.probeCount(); ++probe)
    EXPECT_GT(glm::length(grid.probePosition(probe) - glm::vec3(0.0f, 0.5f, 0.0f)), 0.5f) << probe;
}

TEST(IrradianceVolume, AnAtlasTooLargeIsRefusedWithTheFix) {
  try {
    makeProbeGrid({0, 0, 0}, {1, 1, 1}, 16, 64, 1 << 25);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lower grid or face"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace gib::rt
