#include "support/technique_frame.h"

#include "common/input_error.h"
#include "reference/embree_scene.h"
#include "scene/mesh_builder.h"

#include <gtest/gtest.h>

#include <limits>

namespace gib::test {

scene::Scene floorScene() {
  scene::Scene s;
  s.name = "floor";
  s.camera.position = {0.0f, 3.0f, 0.0f};
  s.camera.look_at = {0.0f, 0.0f, 0.0f};
  s.camera.up = {0.0f, 0.0f, -1.0f};
  s.camera.vertical_fov_deg = 50.0f;
  scene::Material floor;
  floor.name = "floor";
  floor.diffuse = scene::Rgb(0.5f);
  s.materials.push_back(floor);
  scene::Mesh mesh;
  mesh.name = "floor";
  scene::appendQuad(mesh, {-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2});
  s.meshes.push_back(mesh);
  return s;
}

rt::TechniqueRunResult renderOneFrame(const scene::Scene& scene, const std::string& technique,
                                      const std::vector<std::string>& set, int size) {
  const rt::TechniqueInfo& info = rt::findTechnique(technique);
  const ParameterValues values = parseParameters(info.parameters, set, technique);
  rt::TechniqueRunSettings settings;
  settings.width = settings.height = size;
  settings.warmup_frames = 0;
  settings.frames = 1;
  settings.context.debug = true;
  settings.services.ray_caster = ref::embreeRayCasterFactory();  // for techniques that trace rays
  return rt::runTechnique(scene, info, values, settings);
}

namespace {

ref::RenderSettings classReferenceSettings(int size, std::uint32_t spp,
                                           scene::PathClass path_class) {
  ref::RenderSettings settings;
  settings.width = settings.height = size;
  settings.spp = spp;
  settings.path_class = path_class;
  return settings;
}

}  // namespace

ref::RenderResult renderClassReference(const scene::Scene& scene, int size, std::uint32_t spp,
                                       scene::PathClass path_class, std::uint32_t replicas) {
  ref::RenderSettings settings = classReferenceSettings(size, spp, path_class);
  settings.replicas = replicas;
  return ref::renderReference(scene, settings);
}

ref::RenderResult renderCentreClassReference(const scene::Scene& scene, int size, std::uint32_t spp,
                                             scene::PathClass path_class) {
  ref::RenderSettings settings = classReferenceSettings(size, spp, path_class);
  settings.pixel_sampling = ref::PixelSampling::kCenter;
  return ref::renderReference(scene, settings);
}

double statisticNamed(const std::vector<rt::TechniqueStatistic>& statistics,
                      std::string_view name) {
  for (const rt::TechniqueStatistic& s : statistics)
    if (s.name == name) return s.value;
  ADD_FAILURE() << "no statistic '" << name << "'";
  return std::numeric_limits<double>::quiet_NaN();
}

void expectParametersRefused(const std::string& technique,
                             const std::vector<std::string>& assignments) {
  const rt::TechniqueInfo& info = rt::findTechnique(technique);
  for (const std::string& bad : assignments) {
    try {
      parseParameters(info.parameters, {bad}, "technique '" + technique + "'");
      ADD_FAILURE() << bad << " was accepted";
    } catch (const InputError& e) {
      const std::string key = bad.substr(0, bad.find('='));
      EXPECT_NE(std::string(e.what()).find("parameter '" + key + "'"), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace gib::test
