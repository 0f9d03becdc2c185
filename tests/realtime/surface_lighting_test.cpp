// The surface-lighting block every technique draws first (G-buffer, emission, direct light): its
// passes are the ones techniques declare, and its two halves add up to the whole, so a technique
// that lights extra views (probes) or weighs batches between them sees the same light.
#include "realtime/lighting/surface_lighting.h"

#include "realtime/gl/pass_profiler.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/render_target.h"
#include "scene/mesh_builder.h"
#include "support/gl_test_context.h"
#include "support/technique_frame.h"

#include <gtest/gtest.h>

#include <cmath>

namespace gib::rt {
namespace {

class SurfaceLightingTest : public test::GlTest {};

TEST(SurfaceLightingPasses, DeclareTheGBufferTheEmissionAndEveryViewsLight) {
  PassDeclarations passes;
  SurfaceLighting::declarePasses(passes, {{"probe light", "light added into the probes"}});
  for (const char* path : {"frame/g-buffer", "frame/emission", "frame/lights",
                           "frame/lights/shading", "frame/lights/probe light"})
    EXPECT_TRUE(passes.declares(path)) << path;
}

// A floor lit by a spot light, with an emissive tile that the camera sees.
scene::Scene litFloor() {
  scene::Scene s = test::floorScene();
  scene::SpotLight spot;
  spot.position = {0.5f, 1.5f, 0.0f};
  spot.direction = {0.0f, -1.0f, 0.0f};
  spot.intensity = {3, 3, 3};
  spot.cone_angle_deg = 70.0f;
  s.spot_lights.push_back(spot);
  scene::Material tile;
  tile.name = "tile";
  tile.emission = scene::Rgb(2.0f);
  s.materials.push_back(tile);
  scene::Mesh mesh;
  mesh.name = "tile";
  mesh.material = 1;
  scene::appendQuad(mesh, {-1.5f, 0.01f, -1.5f}, {-1.5f, 0.01f, -1.0f}, {-1.0f, 0.01f, -1.0f},
                    {-1.0f, 0.01f, -1.5f});
  s.meshes.push_back(mesh);
  return s;
}

TEST_F(SurfaceLightingTest, SurfacesAndDirectLightAddUpToTheWholeImage) {
  constexpr int kSize = 24;
  const scene::Scene floor = litFloor();  // the GPU scene refers to it
  const GpuScene scene(floor, kSize, kSize);
  SurfaceLighting lighting(
      parseParameters(SurfaceLighting::parameters(), {"light_samples=4"}, "surface lighting"));
  lighting.prepare(scene, kSize, kSize);
  gl::PassProfiler untimed;
  const RenderTarget whole(kSize, kSize), surfaces(kSize, kSize), direct(kSize, kSize);
  whole.clear(0, 0, 0);
  lighting.render(scene, whole, untimed);
  surfaces.clear(0, 0, 0);
  lighting.drawSurfaces(scene, surfaces, untimed);
  direct.clear(0, 0, 0);
  lighting.addDirect(scene, nullptr, untimed, {LitView{&lighting.gbuffer(), &direct}});
  const image::Image w = whole.read(), s = surfaces.read(), d = direct.read();
  double emitted = 0, lit = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      for (int c = 0; c < 3; ++c) {
        const float sum = s.pixel(x, y)[c] + d.pixel(x, y)[c];
        EXPECT_NEAR(w.pixel(x, y)[c], sum, 1e-5f * std::max(1.0f, sum)) << x << ", " << y;
        emitted += s.pixel(x, y)[c];
        lit += d.pixel(x, y)[c];
      }
  EXPECT_GT(emitted, 0.0) << "the camera sees the emissive tile";
  EXPECT_GT(lit, 0.0) << "the spot light reaches the floor";
  EXPECT_EQ(lighting.lighting().sampleCount(), 5u) << "the spot and 4 points on the tile";
}

}  // namespace
}  // namespace gib::rt
