// Light samples in batches (realtime/lighting/shadow_maps.h): a batch's shadow maps are the
// layers of one array drawn by one instanced draw, and one pass lights a view with the whole
// batch. The image must be the one the per-sample passes gave (batches of one) and must not
// depend on where the layer is selected (vertex or geometry shader), on a scene whose point
// lights need all six cube faces, and on one lit by directional lights and the sky.
#include "realtime/gbuffer/gbuffer.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/lighting/direct_lighting.h"
#include "realtime/lighting/light_sample_shared.h"
#include "realtime/lighting/shadow_maps.h"
#include "realtime/render_target.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"
#include "support/gl_test_context.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace gib::rt {
namespace {

using test::GlTest;

scene::Material grey() {
  scene::Material m;
  m.name = "grey";
  m.diffuse = scene::Rgb(0.6f);
  return m;
}

// A closed box around three omnidirectional spot lights, each ringed by six small occluders, one
// along each axis: every cube face of every light casts a shadow onto a wall.
scene::Scene boxOfOccludedLights() {
  scene::Scene s;
  s.name = "box of occluded lights";
  s.materials.push_back(grey());
  scene::Mesh mesh;
  mesh.name = "walls and occluders";
  const float w = 2.0f;
  scene::appendQuad(mesh, {-w, -w, -w}, {w, -w, -w}, {w, -w, w}, {-w, -w, w});
  scene::appendQuad(mesh, {-w, w, -w}, {-w, w, w}, {w, w, w}, {w, w, -w});
  scene::appendQuad(mesh, {-w, -w, -w}, {-w, -w, w}, {-w, w, w}, {-w, w, -w});
  scene::appendQuad(mesh, {w, -w, -w}, {w, w, -w}, {w, w, w}, {w, -w, w});
  scene::appendQuad(mesh, {-w, -w, -w}, {-w, w, -w}, {w, w, -w}, {w, -w, -w});
  scene::appendQuad(mesh, {-w, -w, w}, {w, -w, w}, {w, w, w}, {-w, w, w});
  const float r = 0.25f, d = 0.8f;
  for (int axis = 0; axis < 3; ++axis)
    for (float side : {-1.0f, 1.0f}) {
      glm::vec3 c(0.0f), u(0.0f), v(0.0f);
      c[axis] = side * d;
      u[(axis + 1) % 3] = r;
      v[(axis + 2) % 3] = r;
      scene::appendQuad(mesh, c - u - v, c + u - v, c + u + v, c - u + v);
    }
  s.meshes.push_back(mesh);
  for (glm::vec3 p :
       {glm::vec3(0.0f), glm::vec3(0.3f, 0.1f, -0.2f), glm::vec3(-0.2f, -0.3f, 0.1f)}) {
    scene::SpotLight light;
    light.position = p;
    light.intensity = scene::Rgb(2.0f);
    light.cone_angle_deg = 180.0f;
    s.spot_lights.push_back(light);
  }
  s.camera.vertical_fov_deg = 100.0f;
  return s;
}

// A floor with (or without) a square occluder above it, under two directional lights and the sky.
scene::Scene floorUnderSkyAndSun(bool occluder = true) {
  scene::Scene s;
  s.name = "floor under sky and sun";
  s.materials.push_back(grey());
  scene::Mesh mesh;
  mesh.name = "floor and occluder";
  scene::appendQuad(mesh, {-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2});
  if (occluder)
    scene::appendQuad(mesh, {-0.5f, 1, -0.5f}, {-0.5f, 1, 0.5f}, {0.5f, 1, 0.5f}, {0.5f, 1, -0.5f});
  s.meshes.push_back(mesh);
  s.directional_lights.push_back({glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f)), scene::Rgb(1.5f)});
  s.directional_lights.push_back({glm::normalize(glm::vec3(-0.5f, -1.0f, 0.1f)), scene::Rgb(0.7f)});
  s.sky_radiance = scene::Rgb(0.2f);
  s.camera.position = {0.0f, 4.0f, 2.5f};
  s.camera.look_at = {0.0f, 0.0f, 0.0f};
  s.camera.vertical_fov_deg = 60.0f;
  return s;
}

image::Image renderDirect(const scene::Scene& scene, const ShadowSettings& settings,
                          int light_samples) {
  const int w = 64, h = 64;
  GpuScene gpu(scene, w, h);
  GBuffer gbuffer(w, h);
  RenderTarget target(w, h);
  DirectLighting lighting(settings, light_samples);
  lighting.prepare(gpu);
  gl::PassProfiler profiler;  // outside a frame its passes are no-ops
  gbuffer.render(gpu);
  lighting.writeEmission(gpu, gbuffer, target, profiler);
  lighting.addDirect(gpu, {{&gbuffer, &target}}, profiler);
  return target.read();
}

// Largest difference relative to the image's largest value.
double largestRelativeDifference(const image::Image& a, const image::Image& b) {
  double largest = 0, peak = 0;
  for (std::size_t i = 0; i < a.data().size(); ++i) {
    largest = std::max(largest, double(std::abs(a.data()[i] - b.data()[i])));
    peak = std::max(peak, double(std::abs(a.data()[i])));
  }
  return peak > 0 ? largest / peak : largest;
}

// Share of pixels darker than `fraction` of the image's mean: the shadows the test must see.
double shadowedShare(const image::Image& image, double fraction) {
  double mean = 0;
  for (float v : image.data()) mean += v;
  mean /= double(image.data().size());
  std::size_t dark = 0;
  for (float v : image.data()) dark += v < fraction * mean ? 1 : 0;
  return double(dark) / double(image.data().size());
}

class ShadowBatches : public GlTest {};

TEST_F(ShadowBatches, PointLightsNeedingEveryCubeFaceGiveTheImageOfPerSamplePasses) {
  for (const ShadowFilter filter :
       {ShadowFilter::kHard, ShadowFilter::kPcf, ShadowFilter::kVariance})
    for (int corner : {1, -1}) {
      scene::Scene scene = boxOfOccludedLights();
      // From inside one corner towards the opposite one: three walls, then the other three.
      scene.camera.position = glm::vec3(1.8f * float(corner));
      scene.camera.look_at = glm::vec3(-2.0f * float(corner));
      scene.camera.up = glm::normalize(glm::vec3(0.0f, 1.0f, -0.5f));
      ShadowSettings settings;
      settings.filter = filter;
      settings.size = 128;
      const image::Image batched = renderDirect(scene, settings, 1);
      settings.batch_capacity = 1;
      const image::Image one_by_one = renderDirect(scene, settings, 1);
      settings.batch_capacity = 0;
      settings.layer_from_geometry_shader = true;
      const image::Image geometry_shader = renderDirect(scene, settings, 1);
      EXPECT_GT(shadowedShare(batched, 0.1), 0.01) << "the occluders cast no shadow";
      // Float sums in another order: a few ulps of the brightest pixel.
      EXPECT_LT(largestRelativeDifference(batched, one_by_one), 1e-5)
          << "filter " << int(filter) << ", corner " << corner;
      EXPECT_LT(largestRelativeDifference(batched, geometry_shader), 1e-6)
          << "filter " << int(filter) << ", corner " << corner;
    }
}

TEST_F(ShadowBatches, DirectionalLightsAndSkyGiveTheImageOfPerSamplePasses) {
  const scene::Scene scene = floorUnderSkyAndSun();
  ShadowSettings settings;
  settings.filter = ShadowFilter::kPcf;
  settings.size = 128;
  const image::Image batched = renderDirect(scene, settings, 12);
  settings.batch_capacity = 1;
  const image::Image one_by_one = renderDirect(scene, settings, 12);
  settings.batch_capacity = 5;  // batches that end inside the sky's directions
  const image::Image fives = renderDirect(scene, settings, 12);
  // The occluder's shadows: pixels at least 20% darker than without it.
  const image::Image open = renderDirect(floorUnderSkyAndSun(false), settings, 12);
  std::size_t shadowed = 0;
  for (std::size_t i = 0; i < open.data().size(); ++i)
    shadowed += batched.data()[i] < 0.8f * open.data()[i] ? 1 : 0;
  EXPECT_GT(double(shadowed) / double(open.data().size()), 0.01) << "the occluder casts no shadow";
  EXPECT_LT(largestRelativeDifference(batched, one_by_one), 1e-5);
  EXPECT_LT(largestRelativeDifference(batched, fives), 1e-5);
}

// Each shadow face draws only the triangle chunks its frustum may touch in front of its sample's
// clip plane (view_culling.h): the same image as every triangle drawn into every face, bit for
// bit, on the chamber (3 384 triangles, a spot light's samples: five faces each, clipped) and on
// the box of occluded lights (all six faces, no clip plane), for each filter.
TEST_F(ShadowBatches, CulledFacesGiveTheImageOfEveryTriangleInEveryFace) {
  scene::Scene box = boxOfOccludedLights();
  box.camera.position = glm::vec3(1.8f);
  box.camera.look_at = glm::vec3(-2.0f);
  box.camera.up = glm::normalize(glm::vec3(0.0f, 1.0f, -0.5f));
  const scene::Scene chamber = scene::loadScene("chamber");
  for (const scene::Scene* scene : {&chamber, static_cast<const scene::Scene*>(&box)})
    for (const ShadowFilter filter :
         {ShadowFilter::kHard, ShadowFilter::kPcf, ShadowFilter::kVariance}) {
      ShadowSettings settings;
      settings.filter = filter;
      settings.size = 128;
      const image::Image culled = renderDirect(*scene, settings, 4);
      settings.cull_faces = false;
      const image::Image everything = renderDirect(*scene, settings, 4);
      EXPECT_GT(shadowedShare(culled, 0.1), 0.01) << scene->name << ": no shadows to compare";
      EXPECT_TRUE(std::equal(culled.data().begin(), culled.data().end(), everything.data().begin()))
          << scene->name << ", filter " << int(filter);
    }
}

// The variance shadow map's filter (vsm_blur.comp.glsl: a segment of each line per invocation,
// its window in registers) gives each texel of a drawn face the (2r+1)² box mean of the
// unfiltered moments, taps clamped at the face's edges; a face the sample cannot light is not
// filtered and keeps its cleared moments. A spot light under the ceiling of a box, its 60° cone
// downwards: five faces drawn, the upward one not.
TEST_F(ShadowBatches, VarianceFilterIsTheBoxMeanOfEachDrawnFace) {
  const scene::Scene scene = boxOfOccludedLights();
  GpuScene gpu(scene, 16, 16);
  LightSample spot;
  spot.position = {0.1f, 1.2f, -0.3f};
  spot.axis = {0.0f, -1.0f, 0.0f};
  spot.intensity = scene::Rgb(1.0f);
  spot.cos_cone = 0.5f;
  constexpr int kSize = 64, kRadius = 2;
  auto moments = [&](int radius) {
    ShadowSettings settings;
    settings.filter = ShadowFilter::kVariance;
    settings.size = kSize;
    settings.blur_radius = radius;
    ShadowMaps maps(settings, gpu, 1);
    gl::PassProfiler profiler;
    maps.render(gpu, std::span<const LightSample>(&spot, 1), profiler);
    std::vector<glm::vec2> texels(6 * kSize * kSize);
    glGetTextureImage(maps.lookupMaps().id(), 0, GL_RG, GL_FLOAT,
                      GLsizei(texels.size() * sizeof(glm::vec2)), texels.data());
    return texels;
  };
  const std::vector<glm::vec2> raw = moments(0), filtered = moments(kRadius);
  const int kUpFace = 2;  // +y
  int shadowed_texels = 0;
  for (int face = 0; face < 6; ++face)
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        auto at = [&](const std::vector<glm::vec2>& t, int i, int j) {
          return t[std::size_t((face * kSize + std::clamp(j, 0, kSize - 1)) * kSize +
                               std::clamp(i, 0, kSize - 1))];
        };
        const glm::vec2 got = at(filtered, x, y);
        if (face == kUpFace) {
          ASSERT_EQ(got, glm::vec2(1e4f, 1e8f)) << "the unlit face stays cleared";
          continue;
        }
        glm::vec2 mean(0.0f);
        for (int j = -kRadius; j <= kRadius; ++j)
          for (int i = -kRadius; i <= kRadius; ++i) mean += at(raw, x + i, y + j);
        mean /= float((2 * kRadius + 1) * (2 * kRadius + 1));
        ASSERT_NEAR(got.x, mean.x, 1e-5f * std::max(1.0f, std::abs(mean.x)))
            << "face " << face << " texel " << x << "," << y;
        ASSERT_NEAR(got.y, mean.y, 1e-5f * std::max(1.0f, std::abs(mean.y)))
            << "face " << face << " texel " << x << "," << y;
        if (at(raw, x, y).x < 1.0f) ++shadowed_texels;
      }
  EXPECT_GT(shadowed_texels, 5 * kSize * kSize / 4);  // the drawn faces saw walls
}

TEST(LightSampleBatches, BatchesHoldOneKindAndAtMostTheCapacityInOrder) {
  std::vector<LightSample> samples(7);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    samples[i].kind = i < 4 ? LightSampleKind::kPoint : LightSampleKind::kDirectional;
    samples[i].exponent = float(i);  // the order, to check
  }
  const auto batches = lightSampleBatches(samples, 3);
  ASSERT_EQ(batches.size(), 3u);  // points 3 + 1, directions 3
  const std::size_t sizes[] = {3, 1, 3};
  float next = 0;
  for (std::size_t b = 0; b < batches.size(); ++b) {
    EXPECT_EQ(batches[b].size(), sizes[b]);
    for (const LightSample& sample : batches[b]) {
      EXPECT_EQ(sample.kind, batches[b].front().kind);
      EXPECT_EQ(sample.exponent, next++);
    }
  }
  EXPECT_TRUE(lightSampleBatches({}, 4).empty());
  EXPECT_THROW(lightSampleBatches(samples, 0), std::invalid_argument);
}

TEST(LightSampleBatches, CapacityFollowsTheMemoryBudgetAndTheUniformBlock) {
  ShadowSettings hard;
  hard.size = 512;  // 6 MiB a cube map
  EXPECT_EQ(shadowBatchCapacity(hard, 100), gpu::kMaxLightBatch);
  EXPECT_EQ(shadowBatchCapacity(hard, 16), 16);
  EXPECT_EQ(shadowBatchCapacity(hard, 0), 1);
  ShadowSettings variance = hard;
  variance.filter = ShadowFilter::kVariance;  // 30 MiB a cube map with its moments
  EXPECT_EQ(shadowBatchCapacity(variance, 100), 8);
  hard.size = 4096;  // 384 MiB a cube map: one at a time
  EXPECT_EQ(shadowBatchCapacity(hard, 100), 1);
  hard.batch_capacity = 5;
  EXPECT_EQ(shadowBatchCapacity(hard, 100), 5);
  EXPECT_EQ(shadowBatchCapacity(hard, 3), 3);
}

}  // namespace
}  // namespace gib::rt
