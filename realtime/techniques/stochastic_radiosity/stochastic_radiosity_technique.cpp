#include "realtime/techniques/stochastic_radiosity/stochastic_radiosity_technique.h"

#include "common/splitmix.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/pipeline_state.h"
#include "realtime/gl/shader_library.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/render_target.h"
#include "realtime/technique_parameters.h"
#include "realtime/techniques/stochastic_radiosity/light_injection.h"
#include "realtime/techniques/stochastic_radiosity/stochastic_radiosity_shared.h"

#include <glm/geometric.hpp>

#include <string>

namespace gib::rt {

namespace {

StochasticRadiositySettings settingsFrom(const ParameterValues& p) {
  StochasticRadiositySettings s;
  s.atlas_resolution = p.integer("atlas");
  s.selection = p.text("selection") == "cpu" ? SelectionMethod::kCpu : SelectionMethod::kGpu;
  s.projection = p.text("projection") == "hemisphere" ? ShooterProjection::kHemisphere
                                                      : ShooterProjection::kHemicube;
  s.visibility_size = p.integer("hemicube");
  s.tessellation = p.integer("tessellation");
  s.seed = std::uint32_t(p.integer("seed"));
  return s;
}

}  // namespace

StochasticRadiosityTechnique::StochasticRadiosityTechnique(const ParameterValues& parameters)
    : settings_(settingsFrom(parameters)) {}

StochasticRadiosityTechnique::StochasticRadiosityTechnique(
    const StochasticRadiositySettings& settings)
    : settings_(settings) {}

float StochasticRadiosityTechnique::selectionValue(std::uint32_t seed, int iteration) {
  const std::uint64_t h =
      splitMix64((std::uint64_t(seed) << 32) ^ std::uint64_t(std::uint32_t(iteration)));
  return float(h >> 40) * 0x1p-24f;  // 24 bits: every value exact and below 1
}

void StochasticRadiosityTechnique::prepare(const GpuScene& scene, int /*width*/, int /*height*/) {
  scene_ = &scene;
  const int r = settings_.atlas_resolution;

  // Step 1: the atlas, its maps and the (tessellated) mesh with atlas coordinates.
  triangles_ = atlas::atlasTriangles(scene.scene());
  layout_ = atlas::layoutAtlas(triangles_, r);
  texels_ = atlas::bakeAtlasTexels(triangles_, layout_);
  atlas_.emplace(texels_, triangles_, scene.scene());
  mesh_.emplace(triangles_, layout_, settings_.tessellation);
  const float extent = std::max(glm::length(scene.boundsMax() - scene.boundsMin()), 1e-6f);
  selection_.emplace(settings_.selection, r);
  visibility_.emplace(settings_.projection, settings_.visibility_size, extent);

  // Step 2: the source map, emission plus the injected direct light of point and directional
  // lights.
  source_ = gl::Texture::make2D(GL_RGBA32F, r, r);
  glCopyImageSubData(atlas_->emission().id(), GL_TEXTURE_2D, 0, 0, 0, 0, source_.id(),
                     GL_TEXTURE_2D, 0, 0, 0, 0, r, r, 1);
  source_framebuffer_.attachColor(0, source_);
  source_framebuffer_.setDrawBuffers(1);
  source_framebuffer_.checkComplete();
  injectDirectLight(scene, *atlas_, source_framebuffer_);

  // Step 3: the reflected estimate starts at zero.
  const float zero[4] = {0, 0, 0, 0};
  for (int k = 0; k < 2; ++k) {
    reflected_[std::size_t(k)] = gl::Texture::make2D(GL_RGBA32F, r, r);
    glClearTexImage(reflected_[std::size_t(k)].id(), 0, GL_RGBA, GL_FLOAT, zero);
    gl::Framebuffer& fb = update_[std::size_t(k)];
    fb.attachColor(0, reflected_[std::size_t(k)]);
    fb.attachColor(1, selection_->powerMap(), 0);
    fb.setDrawBuffers(2);
    fb.checkComplete();
  }
  update_pass_ = gl::FullScreenPass("realtime/techniques/stochastic_radiosity/update.frag.glsl",
                                    visibility_->defines());
  const gl::Program& update = update_pass_.program();
  visibility_->setLookupConstants(update);
  update.set("u_texel_area", layout_.texels_per_unit > 0
                                 ? 1.0f / (layout_.texels_per_unit * layout_.texels_per_unit)
                                 : 0.0f);
  view_program_ = gl::buildProgram(
      {{GL_VERTEX_SHADER, "realtime/atlas/atlas_view.vert.glsl"},
       {GL_FRAGMENT_SHADER, "realtime/techniques/stochastic_radiosity/view.frag.glsl"}});

  // Step 4: the power of the initial estimate (emission and injected light alone): an update
  // with no shooter (the Shooters buffer starts empty) and m = 1; then its pyramid.
  iteration_ = 0;
  current_ = 0;
  runUpdatePass();
  selection_->buildPyramid();
}

void StochasticRadiosityTechnique::runUpdatePass() {
  const int r = settings_.atlas_resolution;
  const int next = 1 - current_;
  update_[std::size_t(next)].bind();
  const gl::PipelineScope state({.viewport = gl::PixelRect{0, 0, r, r}});
  update_pass_.program().set("u_iteration", float(std::max(iteration_, 1)));
  atlas_->bind();
  source_.bind(gpu::kRadiositySourceUnit);
  reflected_[std::size_t(current_)].bind(gpu::kRadiosityReflectedUnit);
  visibility_->bindForLookup();
  selection_->bindShooter();
  update_pass_.draw();
  current_ = next;
}

void StochasticRadiosityTechnique::step(gl::PassProfiler& profiler) {
  ++iteration_;
  {
    auto pass = profiler.pass(kSelectionPass);
    selection_->select({selectionValue(settings_.seed, iteration_)});
  }
  {
    auto pass = profiler.pass(kVisibilityPass);
    atlas_->bind();
    selection_->bindShooter();
    visibility_->render(*mesh_);
  }
  {
    auto pass = profiler.pass(kUpdatePass);
    runUpdatePass();
  }
  if (settings_.selection == SelectionMethod::kGpu) {
    auto pass = profiler.pass(kMipmapPass);
    selection_->buildPyramid();
  }
}

void StochasticRadiosityTechnique::render(Frame& frame) {
  auto pass = frame.profiler.pass(kViewPass);
  const scene::Rgb sky = scene_->scene().sky_radiance;
  frame.target.clear(sky.r, sky.g, sky.b);  // what rays that leave the scene see
  frame.target.bind();
  // The nearest surface wins; both sides of a surface are drawn.
  const gl::PipelineScope state({.depth_test = GL_LESS});
  view_program_.use();
  scene_->bindSceneBuffers();
  atlas_->bind();
  source_.bind(gpu::kRadiositySourceUnit);
  reflected_[std::size_t(current_)].bind(gpu::kRadiosityReflectedUnit);
  mesh_->draw();
}

image::Image StochasticRadiosityTechnique::atlasImage() const {
  image::Image radiance = gl::readTexture(source_, 3);
  const image::Image reflected = gl::readTexture(reflected_[std::size_t(current_)], 3);
  for (std::size_t i = 0; i < radiance.data().size(); ++i)
    radiance.data()[i] += reflected.data()[i];
  return radiance;
}

std::vector<glm::vec3> StochasticRadiosityTechnique::atlasRadiance() const {
  return atlas::atlasTexelValues(atlasImage());
}

std::vector<AuxiliaryImage> StochasticRadiosityTechnique::auxiliaryImages() {
  return {{"atlas",
           "radiance atlas (emission + injected direct light + reflected estimate) after " +
               std::to_string(iteration_) + " iterations",
           atlasImage()}};
}

std::vector<TechniqueStatistic> StochasticRadiosityTechnique::statistics() const {
  return {{"vertices", double(mesh_ ? mesh_->vertexCount() : 0)},
          {"atlas_texels", double(texels_.covered)}};
}

TechniqueInfo stochasticRadiosityTechniqueInfo() {
  TechniqueInfo info;
  info.name = "stochastic_radiosity";
  info.description =
      "diffuse GI (L D* E) by stochastic iteration: random texel shooting into a radiance atlas, "
      "hemicube or hemispherical visibility; iterations by --iterations; sky and glossy lobes "
      "left out";
  info.source =
      "Barsi & Jakab, Stream Processing in Global Illumination; Szirmay-Kalos et al., GPU-Based "
      "Techniques for Global Illumination Effects, §7.1";
  info.parameters = {
      atlasParameter(128,
                     "radiance atlas texels per side (the book's 128; the paper's 512 and 1024)"),
      choiceParameter("selection", "gpu", {"gpu", "cpu"},
                      "texel selection: summed pyramid and hierarchical descent on the GPU, or "
                      "read-back and linear search on the CPU (the paper's first version)"),
      choiceParameter("projection", "hemicube", {"hemicube", "hemisphere"},
                      "shooter visibility: five hemicube faces (the book) or one hemispherical "
                      "projection (the paper; exact only for small triangles)"),
      numericParameter("hemicube", ParameterType::kInteger, "256", 16, 2048, "texels",
                       "visibility map resolution: per hemicube face, or of the hemisphere's disk"),
      numericParameter("tessellation", ParameterType::kInteger, "0", 0, 5, "levels",
                       "split every triangle into 4 per level for the technique's draws (the "
                       "atlas is unchanged)"),
      seedParameter("random sequence of the texel selections, the same every run"),
  };
  PassDeclarations& passes = info.passes;
  passes.add(passPath({kFramePass, kViewPass}),
             "the camera view: bilinear lookups of the atlas plus the emitters' front sides");
  passes.add(std::string(kIterationPass), "one shot: a texel selected, its light transferred");
  passes.add(passPath({kIterationPass, kSelectionPass}),
             "a texel chosen with probability proportional to its power");
  passes.add(passPath({kIterationPass, kVisibilityPass}),
             "the scene drawn from the shooter into its visibility map");
  passes.add(passPath({kIterationPass, kUpdatePass}),
             "every texel in texture space: transfer and the running average of eq. (2)");
  passes.add(passPath({kIterationPass, kMipmapPass}),
             "the power pyramid for the next selection (GPU selection only)");
  info.auxiliary_images = {
      {"atlas", "radiance atlas (emission + injected direct light + reflected estimate)"},
  };
  info.statistics = {
      {"vertices", "vertices drawn per view of the scene"},
      {"atlas_texels", "atlas texels covered by a surface"},
  };
  info.create = [](const ParameterValues& values) -> std::unique_ptr<Technique> {
    return std::make_unique<StochasticRadiosityTechnique>(values);
  };
  return info;
}

}  // namespace gib::rt
