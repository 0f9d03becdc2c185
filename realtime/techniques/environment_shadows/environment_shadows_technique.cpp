#include "realtime/techniques/environment_shadows/environment_shadows_technique.h"

#include "common/elapsed.h"
#include "common/input_error.h"
#include "realtime/gpu_scene/glossy_exponents.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/lighting/cell_reflectivity_shared.h"
#include "realtime/lighting/environment_texture.h"
#include "realtime/technique_parameters.h"
#include "realtime/techniques/environment_shadows/cap_reflectivity.h"
#include "scene/scene.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <memory>
#include <string>

namespace gib::rt {

namespace {

// A scene with a constant sky (the need admits one) is lit by a constant map of this many rows:
// fine enough that every allowed cell count has texels to hold it.
constexpr int kConstantSkyRows = 64;

// Each non-empty cell as a directional light at its centre carrying its power; with the
// integrated reflectivity, the half-angle of the cap of its solid angle too.
std::vector<LightSample> cellSamples(const EnvironmentCells& cells, bool integrated) {
  std::vector<LightSample> samples;
  for (const EnvironmentCell& cell : cells.cells) {
    if (cell.texels == 0 || scene::luminance(cell.power) <= 0) continue;
    LightSample s;
    s.kind = LightSampleKind::kDirectional;
    s.axis = -cell.direction;
    s.intensity = cell.power;
    s.cap_half_angle = integrated ? float(capHalfAngle(cell.solid_angle)) : 0.0f;
    samples.push_back(s);
  }
  return samples;
}

}  // namespace

EnvironmentShadowsTechnique::EnvironmentShadowsTechnique(const ParameterValues& p)
    : surface_lighting_(p),
      cell_count_(p.integer("cells")),
      relaxation_steps_(p.integer("relaxation_steps")),
      integrated_(p.text("reflectivity") == "integrated") {}

void EnvironmentShadowsTechnique::prepare(const GpuScene& scene, int width, int height) {
  scene_ = &scene;
  map_ = sceneEnvironment(scene.scene(), kConstantSkyRows);
  // Step 1: the cells (§4.2.3's preprocessing), and their Delaunay mesh for Fig. 4.13's image.
  cells_ = buildEnvironmentCells(map_, cell_count_, relaxation_steps_);
  const auto delaunay_start = std::chrono::steady_clock::now();
  triangulation_ = triangulateSphere(cells_.centres);
  delaunay_ms_ = millisecondsSince(delaunay_start);
  // Step 2: the cells replace the shared lighting's own environment samples.
  DirectLighting& lighting = surface_lighting_.lighting();
  lighting.setEnvironmentSamples(false);
  lighting.setExtraSamples(cellSamples(cells_, integrated_));
  if (integrated_) prepareReflectivity(scene.scene());
  surface_lighting_.prepare(scene, width, height);
}

void EnvironmentShadowsTechnique::prepareReflectivity(const scene::Scene& scene) {
  const std::vector<float> exponents = glossyExponents(scene);
  if (exponents.size() > std::size_t(gpu::kMaxCellReflectivityExponents))
    throw InputError(fmt::format(
        "the scene's glossy meshes use {} distinct Phong exponents; environment_shadows' "
        "integrated reflectivity tabulates at most {}: use reflectivity=center or fewer "
        "exponents",
        exponents.size(), gpu::kMaxCellReflectivityExponents));
  const auto start = std::chrono::steady_clock::now();
  const int n = gpu::kCellReflectivitySize;
  reflectivity_ = gl::Texture::make2DArray(GL_R32F, n, n, 1 + int(exponents.size()));
  reflectivity_.setFilter(GL_LINEAR, GL_LINEAR);
  reflectivity_.setWrap(GL_CLAMP_TO_EDGE);
  reflectivity_.upload(capReflectivityTable(1.0).data(), GL_RED, 0, 0);
  for (std::size_t k = 0; k < exponents.size(); ++k)
    reflectivity_.upload(capReflectivityTable(double(exponents[k])).data(), GL_RED, 0, int(k) + 1);
  reflectivity_ms_ = millisecondsSince(start);
  std::string defines = "#define GIB_CELL_REFLECTIVITY\n";
  defines += fmt::format("#define CELL_REFLECTIVITY_LAYERS {}\n", exponents.size());
  if (!exponents.empty())
    defines +=
        fmt::format("#define CELL_REFLECTIVITY_EXPONENTS {}\n", glslExponentArray(exponents));
  surface_lighting_.lighting().setShadingDefines(defines);
}

void EnvironmentShadowsTechnique::render(Frame& frame) {
  // The tables stay bound through the frame: none of the frame's other passes uses the unit.
  if (integrated_) reflectivity_.bind(gpu::kCellReflectivityUnit);
  surface_lighting_.render(*scene_, frame.target, frame.profiler);
}

std::vector<AuxiliaryImage> EnvironmentShadowsTechnique::auxiliaryImages() {
  return {{"cells",
           "the environment map with the Delaunay triangulation of the cells' centres (green) and "
           "the centres (red), as Fig. 4.13; laid out as the map, row 0 the zenith",
           drawCellTriangulation(map_, cells_, triangulation_)}};
}

std::vector<TechniqueStatistic> EnvironmentShadowsTechnique::statistics() const {
  double most = 0, least = std::numeric_limits<double>::infinity(), sum = 0;
  int empty = 0;
  for (const EnvironmentCell& cell : cells_.cells) {
    const double power = scene::luminance(cell.power);
    sum += power;
    if (cell.texels == 0 || power <= 0) {
      ++empty;
      continue;
    }
    most = std::max(most, power), least = std::min(least, power);
  }
  const double integral = scene::luminance(scene::environmentIntegral(map_));
  const double lit = double(cells_.cells.size()) - double(empty);
  return {{"prepare_cells_ms", cells_.total_ms},
          {"relaxation_ms", cells_.relaxation_ms},
          {"delaunay_ms", delaunay_ms_},
          {"prepare_reflectivity_ms", reflectivity_ms_},
          {"cells", double(cells_.cells.size())},
          {"lit_cells", lit},
          {"power_ratio", lit > 0 ? most / least : 0.0},
          {"power_sum_relative", integral > 0 ? sum / integral : 0.0},
          {"delaunay_triangles", double(triangulation_.triangles.size())}};
}

TechniqueInfo environmentShadowsTechniqueInfo() {
  TechniqueInfo info;
  info.name = "environment_shadows";
  info.description =
      "environment map lighting with shadows: the sphere split into cells of equal power "
      "(weighted Lloyd relaxation), each a directional light with its own shadow map; BRDF at "
      "the cell's centre or averaged over it";
  info.source =
      "Szirmay-Kalos et al., GPU-Based Techniques for Global Illumination Effects, §4.2.3 and "
      "Figs. 4.13-4.15; Barsi, Szirmay-Kalos & Szécsi 2005 (the book's [10]) for the average "
      "reflectivity";
  info.parameters = joinParameterTables(
      {{numericParameter("cells", ParameterType::kInteger, "64", 1, 4096, "",
                         "cells of the environment, one directional light and shadow map each "
                         "(the book: 1000 for Fig. 4.15)"),
        numericParameter("relaxation_steps", ParameterType::kInteger, "8", 0, 64, "",
                         "weighted Lloyd relaxation steps after the radiance-proportional draw"),
        choiceParameter("reflectivity", "integrated", {"center", "integrated"},
                        "the BRDF × cos at the cell's centre, or averaged over the cell taken as "
                        "a cap of its solid angle (Fig. 4.14)")},
       SurfaceLighting::parameters()});
  SurfaceLighting::declarePasses(info.passes);
  info.auxiliary_images = {
      {"cells", "the environment map with the cells' Delaunay triangulation (Fig. 4.13)"}};
  info.statistics = {
      {"prepare_cells_ms", "time to draw, relax and sum the cells on the CPU (prepare)"},
      {"relaxation_ms", "of which the Lloyd relaxation steps"},
      {"delaunay_ms", "time to triangulate the centres (for the cells image; prepare)"},
      {"prepare_reflectivity_ms", "time to tabulate the integrated reflectivity (prepare)"},
      {"cells", "cells of the environment"},
      {"lit_cells",
       "cells with texels and light: the directional lights and shadow maps; the "
       "shadow pass time over this is the time per cell"},
      {"power_ratio", "the largest cell power over the smallest (luminance; 1 is equal power)"},
      {"power_sum_relative", "Σ of the cells' powers over the map's integral (1 up to rounding)"},
      {"delaunay_triangles", "triangles of the centres' Delaunay mesh (2·cells − 4)"}};
  // The environment lights by its cells and shows as the background; mirrors and glass are not
  // rendered (the shading passes know Lambert and Phong only).
  info.needs = {TechniqueNeed::kEnvironmentLight};
  info.renders_environment_map = true;
  info.renders_specular_materials = false;
  info.create = [](const ParameterValues& values) -> std::unique_ptr<Technique> {
    return std::make_unique<EnvironmentShadowsTechnique>(values);
  };
  return info;
}

}  // namespace gib::rt
