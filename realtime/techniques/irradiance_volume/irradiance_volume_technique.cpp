#include "realtime/techniques/irradiance_volume/irradiance_volume_technique.h"

#include "realtime/gl/gpu_commands.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/pipeline_state.h"
#include "realtime/gl/shader_library.h"
#include "realtime/render_target.h"
#include "realtime/sh/spherical_harmonics.h"
#include "realtime/techniques/irradiance_volume/irradiance_volume_shared.h"

#include <fmt/format.h>
#include <glm/gtc/type_ptr.hpp>

#include <functional>

namespace gib::rt {

namespace {

// Cube-map texels per buffer at most: 8³ probes with 32² faces, or 16³ with 16².
constexpr long long kMaxAtlasTexels = 1 << 25;

void setGridUniforms(const gl::Program& program, const ProbeGrid& grid, bool indirect_shadows) {
  program.set("u_grid_n", grid.n);
  program.set("u_grid_origin", grid.origin);
  program.set("u_grid_cell", grid.cell);
  const std::array<float, sh::kShMaxBand + 1> lambert = sh::lambertBandFactors();
  static_assert(sh::kShMaxBand + 1 == 4, "u_lambert_factors is a vec4: bands 0..3");
  program.set("u_lambert_factors", glm::make_vec4(lambert.data()));
  program.set("u_indirect_shadows", indirect_shadows ? 1 : 0);
  program.set("u_face", grid.face);
  program.set("u_tiles_x", grid.tiles_x);
}

}  // namespace

IrradianceVolumeTechnique::IrradianceVolumeTechnique(const ParameterValues& p)
    : bounces_(p.integer("bounces")),
      grid_n_(p.integer("grid")),
      face_(p.integer("face")),
      band_(p.integer("sh_order")),
      indirect_shadows_(p.text("indirect_shadows") == "on"),
      rasterise_every_frame_(p.text("motion") == "objects"),
      objects_bounds_(p.text("grid_bounds") == "objects"),
      surface_lighting_(p) {
  // Refused when the technique is created, so a suite is refused before it runs anything.
  checkProbeAtlasSize(grid_n_, face_, kMaxAtlasTexels);
}

void IrradianceVolumeTechnique::prepare(const GpuScene& scene, int width, int height) {
  scene_ = &scene;
  const ProbeBounds bounds = objects_bounds_ ? objectsProbeBounds(scene.scene())
                                             : ProbeBounds{scene.boundsMin(), scene.boundsMax()};
  grid_ = makeProbeGrid(bounds.min, bounds.max, grid_n_, face_, kMaxAtlasTexels);
  const float extent = glm::length(scene.boundsMax() - scene.boundsMin());
  near_ = 1e-4f * extent;
  far_ = 2.0f * extent;
  surface_lighting_.prepare(scene, width, height);
  probe_gbuffer_.emplace(grid_.atlasWidth(), grid_.atlasHeight());
  probe_direct_.emplace(grid_.atlasWidth(), grid_.atlasHeight());
  probe_lit_.emplace(grid_.atlasWidth(), grid_.atlasHeight());

  const int count = sh::shCoefficientCount(band_);
  coefficients_ = gl::Buffer(
      std::size_t(gpu::probeCoefficientIndex(grid_.probeCount(), 0)) * sizeof(glm::vec4), nullptr);
  coefficient_texels_ = gl::Texture::makeBuffer(GL_RGBA32F, coefficients_);
  weights_ = gl::Buffer::fromVector(sh::cubeProjectionWeights(face_, band_));
  std::vector<float> phong;  // per material, bands 0..3
  for (const scene::Material& m : scene.scene().materials) {
    const auto factors = m.type == scene::MaterialType::kPhong
                             ? sh::phongBandFactors(m.exponent)
                             : std::array<float, sh::kShMaxBand + 1>{};
    phong.insert(phong.end(), factors.begin(), factors.end());
  }
  if (phong.empty()) phong.assign(4, 0.0f);
  phong_factors_ = gl::Buffer::fromVector(phong);

  project_ = gl::buildProgram(
      {{GL_COMPUTE_SHADER, "realtime/techniques/irradiance_volume/sh_projection.comp.glsl"}});
  project_.set("u_face", grid_.face);
  project_.set("u_tiles_x", grid_.tiles_x);
  project_.set("u_coefficient_count", count);
  indirect_ = gl::FullScreenPass("realtime/techniques/irradiance_volume/indirect.frag.glsl",
                                 fmt::format("#define SH_COEFFICIENT_COUNT {}\n", count));
  setGridUniforms(indirect_.program(), grid_, indirect_shadows_);
  rasterised_ = false;
}

void IrradianceVolumeTechnique::rasteriseProbes() {
  probe_gbuffer_->renderViews(*scene_, grid_.views(near_, far_));
  rasterised_ = true;
}

void IrradianceVolumeTechnique::project(const RenderTarget& lit) {
  project_.use();
  lit.color().bind(gpu::kProbeRadianceUnit);
  coefficients_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kProbeCoefficientsBinding);
  weights_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kProjectionWeightsBinding);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  gl::dispatchCompute(GLuint(grid_.probeCount()), 1, 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);  // the lookups read them as a buffer texture
}

void IrradianceVolumeTechnique::addIndirect(const GBuffer& gbuffer, const RenderTarget& target,
                                            bool probe_view) {
  scene_->bindSceneBuffers();
  indirect_.use();
  indirect_.program().set("u_normals_face_viewer", probe_view ? 1 : 0);
  gbuffer.bindTextures();
  probe_gbuffer_->position().bind(gpu::kProbePositionUnit);
  coefficient_texels_.bind(gpu::kProbeCoefficientsUnit);
  phong_factors_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kPhongFactorsBinding);
  target.bind();
  const gl::PipelineScope adding({.blend = gl::kAdditiveBlend});
  indirect_.draw();
}

void IrradianceVolumeTechnique::bounce(gl::PassProfiler& profiler,
                                       const std::function<void(int)>& after_bounce) {
  const RenderTarget* lit = &*probe_direct_;
  for (int b = 1; b <= bounces_; ++b) {
    {
      auto pass = profiler.pass(kShProjectionPass);
      project(*lit);
    }
    if (after_bounce) after_bounce(b);
    if (b == bounces_) break;
    // The next bounce sees direct light plus this bounce's indirect light at the probes' surfaces.
    auto pass = profiler.pass(kRelightProbesPass);
    glCopyImageSubData(probe_direct_->color().id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                       probe_lit_->color().id(), GL_TEXTURE_2D, 0, 0, 0, 0, grid_.atlasWidth(),
                       grid_.atlasHeight(), 1);
    addIndirect(*probe_gbuffer_, *probe_lit_, true);
    lit = &*probe_lit_;
  }
}

glm::vec3 IrradianceVolumeTechnique::lightOffset(const Frame& frame) const {
  return rasterise_every_frame_ ? glm::vec3(0.0f) : movingLightOffset(*scene_, frame);
}

void IrradianceVolumeTechnique::render(Frame& frame) {
  gl::PassProfiler& profiler = frame.profiler;
  surface_lighting_.lighting().setLightOffset(lightOffset(frame));
  // Without bounces the probes are never read: the frame is `direct`'s.
  const bool probes = bounces_ > 0;
  if (probes && (rasterise_every_frame_ || !rasterised_)) {
    auto pass = profiler.pass(kRasteriseProbesPass);
    rasteriseProbes();
  }
  surface_lighting_.drawSurfaces(*scene_, frame.target, profiler);
  std::vector<LitView> probe_views;
  if (probes) {
    probe_direct_->clear(0, 0, 0);
    probe_views.push_back({&*probe_gbuffer_, &*probe_direct_, kProbeDirectPass, true});
  }
  surface_lighting_.addDirect(*scene_, &frame.target, profiler, std::move(probe_views));
  bounce(profiler);
  if (bounces_ > 0) {
    auto pass = profiler.pass(kIndirectPass);
    addIndirect(surface_lighting_.gbuffer(), frame.target, false);
  }
}

std::vector<AuxiliaryImage> IrradianceVolumeTechnique::auxiliaryImages() {
  if (bounces_ == 0) return {};
  // Fig. 2 (d, e): the indirect light after each bounce, and what each bounce adds.
  RenderTarget scratch(surface_lighting_.gbuffer().width(), surface_lighting_.gbuffer().height());
  gl::PassProfiler untimed;
  std::vector<AuxiliaryImage> images;
  image::Image previous;
  bounce(untimed, [&](int b) {
    scratch.clear(0, 0, 0);
    addIndirect(surface_lighting_.gbuffer(), scratch, false);
    image::Image total = scratch.read();
    image::Image added = total;
    if (b > 1)
      for (std::size_t i = 0; i < added.data().size(); ++i) added.data()[i] -= previous.data()[i];
    images.push_back({fmt::format("indirect-{}", b),
                      fmt::format("the light bounce {} adds (camera view)", b), added});
    previous = std::move(total);
  });
  images.push_back(
      {"indirect", fmt::format("all indirect light after {} bounces", bounces_), previous});
  return images;
}

std::vector<TechniqueStatistic> IrradianceVolumeTechnique::statistics() const {
  return {{"grid_points", double(grid_.probeCount())},
          {"cube_texels", double(grid_.tileCount()) * grid_.face * grid_.face},
          {"sh_coefficients", double(sh::shCoefficientCount(band_))},
          {"vertices", scene_ ? double(scene_->vertexCount()) : 0.0}};
}

TechniqueInfo irradianceVolumeTechniqueInfo() {
  TechniqueInfo info;
  info.name = "irradiance_volume";
  info.description =
      "irradiance volume: cube maps at grid points projected to spherical harmonics, k bounces "
      "of indirect light over shadow-mapped direct light";
  info.source = "Nijasure, Pattanaik & Goel, Real-Time Global Illumination on GPU (2005)";
  // An environment map lights the surfaces through DirectLighting's light samples and shows as the
  // camera's background; the probes' cube maps keep it out (their background texels stay black),
  // so the volume's indirect light is light reflected by surfaces only, as the reference splits
  // its path classes: the map's light at the first vertex is direct, never indirect.
  info.renders_environment_map = true;
  info.parameters = joinParameterTables(
      {{
           numericParameter(
               "bounces", ParameterType::kInteger, "2", 0, 8, "",
               "iterations of indirect light (the paper's 2); 0 is direct light alone"),
           numericParameter("grid", ParameterType::kInteger, "4", 2, 16, "probes per axis",
                            "uniform grid of n×n×n probes over the scene bounds (the paper's 4)"),
           choiceParameter(
               "grid_bounds", "scene", {"scene", "objects"},
               "the box the grid spans: the scene's bounds, or the bounds of every mesh but the "
               "largest (an outdoor scene's ground) grown by their extent, within the scene's"),
           numericParameter("face", ParameterType::kInteger, "16", 4, 64, "texels",
                            "cube-map face size at each probe (the paper's 16)"),
           numericParameter(
               "sh_order", ParameterType::kInteger, "2", 1, 3, "band",
               "highest spherical-harmonic band: 2 gives the paper's 9 coefficients, 3 "
               "gives 16"),
           choiceParameter("indirect_shadows", "off", {"off", "on"},
                           "§6: weight the eight probes by whether their cube maps see the point"),
           choiceParameter(
               "motion", "objects", {"objects", "light"},
               "what moves between frames: objects (the cube maps are rasterised every "
               "frame, the paper's dynamic scene) or the light (it circles, back at rest "
               "on the last frame; the cube maps are rasterised once)"),
       },
       SurfaceLighting::parameters()});
  PassDeclarations& passes = info.passes;
  passes.add(passPath({kFramePass, kRasteriseProbesPass}),
             "the probes' cube maps as tiles of one G-buffer (every frame with motion=objects)");
  SurfaceLighting::declarePasses(
      passes, {{kProbeDirectPass,
                "light added into the probes' cube maps (Table 1: rendering cube maps "
                "using raster data)"}});
  passes.add(passPath({kFramePass, kShProjectionPass}),
             "eq. 2: the lit cube maps projected to SH coefficients, per bounce");
  passes.add(passPath({kFramePass, kRelightProbesPass}),
             "the cube maps relit with the previous bounce's indirect light");
  passes.add(passPath({kFramePass, kIndirectPass}),
             "eq. 3-6: the last bounce's indirect light added into the camera view");
  info.auxiliary_images = {
      {"indirect-<n>", "the light bounce n adds (camera view)"},
      {"indirect", "all indirect light after the last bounce"},
  };
  info.statistics = {
      {"grid_points", "probes in the grid"},
      {"cube_texels", "texels of all probes' cube maps"},
      {"sh_coefficients", "spherical-harmonic coefficients per probe and channel"},
      {"vertices", "vertices drawn per view of the scene"},
  };
  info.create = [](const ParameterValues& values) -> std::unique_ptr<Technique> {
    return std::make_unique<IrradianceVolumeTechnique>(values);
  };
  return info;
}

}  // namespace gib::rt
