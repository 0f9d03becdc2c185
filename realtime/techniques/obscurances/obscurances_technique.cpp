#include "realtime/techniques/obscurances/obscurances_technique.h"

#include "realtime/gl/finished_time.h"
#include "realtime/gl/gpu_commands.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/pipeline_state.h"
#include "realtime/gl/shader_library.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/technique_parameters.h"
#include "realtime/techniques/obscurances/bundle_set.h"
#include "realtime/techniques/obscurances/obscurances_shared.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <string>

namespace gib::rt {

namespace {

// Layers shown by the peeling figure (book Fig. 10.9 shows six).
constexpr int kFigureLayers = 6;

ObscurancesSettings settingsFrom(const ParameterValues& p) {
  ObscurancesSettings s;
  s.definition.mode = scene::parseObscuranceMode(p.text("mode"));
  s.definition.falloff = scene::parseObscuranceFalloff(p.text("falloff"));
  s.definition.d_max_fraction = float(p.number("d_max"));
  s.directions = p.integer("directions");
  s.peel_resolution = p.integer("peel_resolution");
  s.max_layers = p.integer("max_layers");
  s.atlas_resolution = p.integer("atlas");
  s.light_weighting = p.text("light_weighting") == "distance";
  s.moving_light = p.text("motion") == "light";
  s.output =
      p.text("output") == "obscurance" ? ObscuranceOutput::kObscurance : ObscuranceOutput::kFinal;
  s.seed = std::uint32_t(p.integer("seed"));
  s.shadow = shadowSettings(p);
  s.light_samples = p.integer("light_samples");
  return s;
}

// The power-weighted centre of the scene's lights with a place (area and spot lights), the point
// the light weighting measures distances from; false when the scene has none.
bool lightCentre(const scene::Scene& scene, const std::vector<atlas::AtlasTriangle>& triangles,
                 glm::vec3* centre) {
  glm::dvec3 sum(0.0);
  double weight = 0;
  for (const atlas::AtlasTriangle& t : triangles) {
    const double power = scene::luminance(scene.materials[t.material].emission) * t.area;
    sum += power * glm::dvec3((t.p[0] + t.p[1] + t.p[2]) / 3.0f);
    weight += power;
  }
  for (const scene::SpotLight& spot : scene.spot_lights) {
    // Compare with an area light's π·Lᵉ·A: a spot's power I·∫cosᵏθ dω, over π.
    const double power =
        scene::luminance(spot.intensity) * scene::spotSolidAngleIntegral(spot) / std::numbers::pi;
    sum += power * glm::dvec3(spot.position);
    weight += power;
  }
  if (!(weight > 0)) return false;
  *centre = glm::vec3(sum / weight);
  return true;
}

// For every texel, the texel whose sums it shows: itself when it covers surface; for a gutter
// texel, the covered texel of its chart whose sample point it copies (atlas_layout.h bakes the
// gutter so), found among its neighbours within the gutter's width. xy: that texel, w: 1 when
// there is one.
std::vector<glm::vec4> sourceTexels(const atlas::AtlasTexels& baked) {
  const int r = baked.resolution;
  std::vector<glm::vec4> source(baked.texels.size(), glm::vec4(0.0f));
  for (int y = 0; y < r; ++y)
    for (int x = 0; x < r; ++x) {
      const atlas::AtlasTexel& texel = baked.texels[std::size_t(y * r + x)];
      if (!texel.inChart()) continue;
      if (texel.area > 0) {
        source[std::size_t(y * r + x)] = glm::vec4(float(x), float(y), 0.0f, 1.0f);
        continue;
      }
      float best = std::numeric_limits<float>::max();
      for (int dy = -atlas::kGutterTexels; dy <= atlas::kGutterTexels; ++dy)
        for (int dx = -atlas::kGutterTexels; dx <= atlas::kGutterTexels; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= r || ny >= r) continue;
          const atlas::AtlasTexel& n = baked.texels[std::size_t(ny * r + nx)];
          if (!(n.area > 0)) continue;
          const glm::vec3 gap = n.position - texel.position;
          const float distance = glm::dot(gap, gap);
          if (distance < best) {
            best = distance;
            source[std::size_t(y * r + x)] = glm::vec4(float(nx), float(ny), 0.0f, 1.0f);
          }
        }
    }
  return source;
}

}  // namespace

ObscurancesTechnique::ObscurancesTechnique(const ParameterValues& parameters)
    : settings_(settingsFrom(parameters)) {}

std::optional<scene::ObscuranceDefinition> ObscurancesTechnique::imageObscurance() const {
  if (settings_.output == ObscuranceOutput::kObscurance) return settings_.definition;
  return std::nullopt;
}

void ObscurancesTechnique::prepare(const GpuScene& scene, int width, int height) {
  scene_ = &scene;
  width_ = width;
  height_ = height;
  const int r = settings_.atlas_resolution;
  triangles_ = atlas::atlasTriangles(scene.scene());
  layout_ = atlas::layoutAtlas(triangles_, r);
  texels_ = atlas::bakeAtlasTexels(triangles_, layout_);
  atlas_.emplace(texels_, triangles_, scene.scene());
  mesh_.emplace(triangles_, layout_, 0);

  const scene::SceneAverages averages = scene::sceneAverages(scene.scene());
  ambient_ = scene::ambientLight(averages, settings_.definition.mode);
  average_albedo_ = averages.albedo;
  d_max_ = scene::maxDistance(scene.scene(), settings_.definition);
  has_light_position_ = lightCentre(scene.scene(), triangles_, &light_position_);

  const glm::vec3 low = scene.boundsMin(), high = scene.boundsMax();
  peeler_.emplace(settings_.peel_resolution, settings_.max_layers, 0.5f * (low + high),
                  std::max(0.5f * glm::length(high - low) * 1.01f, 1e-6f));
  sums_ = gl::Texture::make2D(GL_RGBA32F, r, r);
  obscurance_ = gl::Texture::make2D(GL_RGBA32F, r, r);
  source_ = gl::Texture::make2D(GL_RGBA32F, r, r);
  const std::vector<glm::vec4> source = sourceTexels(texels_);
  source_.upload(&source[0].x, GL_RGBA);
  points_.emplace();
  accumulate_program_ = gl::buildProgram(
      {{GL_VERTEX_SHADER, "realtime/techniques/obscurances/accumulate.vert.glsl"},
       {GL_FRAGMENT_SHADER, "realtime/techniques/obscurances/accumulate.frag.glsl"}});
  normalize_pass_ = gl::FullScreenPass("realtime/techniques/obscurances/normalize.frag.glsl");
  view_program_ =
      gl::buildProgram({{GL_VERTEX_SHADER, "realtime/atlas/atlas_view.vert.glsl"},
                        {GL_FRAGMENT_SHADER, "realtime/techniques/obscurances/view.frag.glsl"}});
  buildObscuranceMap();

  if (settings_.output == ObscuranceOutput::kFinal) {
    surface_lighting_.emplace(settings_.shadow, settings_.light_samples);
    surface_lighting_->prepare(scene, width, height);
    ambient_view_.emplace(width, height);
    composite_pass_ = gl::FullScreenPass("realtime/gl/add_image.frag.glsl");
  }
}

void ObscurancesTechnique::buildObscuranceMap() {
  const int r = settings_.atlas_resolution;
  const float zero[4] = {0, 0, 0, 0};
  glClearTexImage(sums_.id(), 0, GL_RGBA, GL_FLOAT, zero);
  gl::Framebuffer sums_framebuffer;
  sums_framebuffer.attachColor(0, sums_);
  sums_framebuffer.setDrawBuffers(1);
  sums_framebuffer.checkComplete();

  const gl::Program& a = accumulate_program_;
  a.use();
  a.set("u_peel_resolution", settings_.peel_resolution);
  a.set("u_atlas_resolution", r);
  a.set("u_spectral", settings_.definition.mode == scene::ObscuranceMode::kSpectral ? 1 : 0);
  a.set("u_falloff", int(settings_.definition.falloff));
  a.set("u_d_max", d_max_);
  a.set("u_average_albedo", average_albedo_);

  build_ = {};
  long long layers_total = 0;
  const std::vector<PeelBundle> bundles =
      obscurance::bundleSet(settings_.directions, settings_.seed);
  for (const PeelBundle& bundle : bundles) {
    int layers = 0;
    build_.peel_ms += gl::finishedMilliseconds([&] { layers = peeler_->peel(*mesh_, bundle); });
    layers_total += layers;
    build_.layers_max = std::max(build_.layers_max, layers);
    if (layers == settings_.max_layers) ++build_.layers_truncated;
    build_.accumulate_ms += gl::finishedMilliseconds([&] {
      sums_framebuffer.bind();
      const gl::PipelineScope adding(
          {.blend = gl::kAdditiveBlend, .viewport = gl::PixelRect{0, 0, r, r}});
      a.use();
      a.set("u_layer_count", layers);
      a.set("u_truncated", layers == settings_.max_layers ? 1 : 0);
      atlas_->bind();
      peeler_->layers().bind(gpu::kPeelLayersUnit);
      points_->bind();
      const long long points =
          (long long)settings_.peel_resolution * settings_.peel_resolution * layers;
      if (points > 0) gl::drawArrays(GL_POINTS, 0, GLsizei(points));
    });
  }
  build_.layers_mean = bundles.empty() ? 0.0 : double(layers_total) / double(bundles.size());

  build_.normalize_ms = gl::finishedMilliseconds([&] {
    gl::Framebuffer framebuffer;
    framebuffer.attachColor(0, obscurance_);
    framebuffer.setDrawBuffers(1);
    framebuffer.checkComplete();
    framebuffer.bind();
    const gl::PipelineScope state({.viewport = gl::PixelRect{0, 0, r, r}});
    const float s = peeler_->pixelSize();
    normalize_pass_.program().set("u_scale",
                                  2.0f * s * s / float(std::max(settings_.directions, 1)));
    atlas_->bind();
    sums_.bind(gpu::kObscuranceSumsUnit);
    source_.bind(gpu::kObscuranceSourceUnit);
    normalize_pass_.draw();
  });
  obscurance_.setFilter(GL_LINEAR, GL_LINEAR);
}

void ObscurancesTechnique::drawView(const RenderTarget& target, bool show_obscurance,
                                    glm::vec3 light_offset) {
  target.clear(0, 0, 0);
  target.bind();
  const gl::PipelineScope state({.depth_test = GL_LESS});
  view_program_.use();
  view_program_.set("u_show_obscurance", show_obscurance ? 1 : 0);
  view_program_.set("u_ambient", ambient_);
  const bool weighting = settings_.light_weighting && has_light_position_;
  view_program_.set("u_light_weighting", weighting ? 1 : 0);
  // Light weighting (README, "Light weighting"): w(x) = 1/(|x − p|² + d_max²) over its mean on the
  // scene's surfaces, so the ambient light's total over the scene is kept and only its place
  // changes; recomputed for the light's place in this frame.
  const glm::vec3 light = light_position_ + light_offset;
  const float offset = d_max_ * d_max_;
  if (weighting && weighted_light_ != light) {
    double weighted = 0, area = 0;
    for (const atlas::AtlasTexel& t : texels_.texels)
      if (t.area > 0) {
        const glm::vec3 to_light = light - t.position;
        weighted += double(t.area) / (double(glm::dot(to_light, to_light)) + offset);
        area += t.area;
      }
    weight_scale_ = weighted > 0 ? float(area / weighted) : 1.0f;
    weighted_light_ = light;
  }
  view_program_.set("u_light_position", light);
  view_program_.set("u_weight_offset", offset);
  view_program_.set("u_weight_scale", weight_scale_);
  scene_->bindSceneBuffers();
  atlas_->bind();
  obscurance_.bind(gpu::kObscuranceMapUnit);
  mesh_->draw();
}

void ObscurancesTechnique::render(Frame& frame) {
  gl::PassProfiler& profiler = frame.profiler;
  const glm::vec3 offset =
      settings_.moving_light ? movingLightOffset(*scene_, frame) : glm::vec3(0.0f);
  last_light_offset_ = offset;
  if (settings_.output == ObscuranceOutput::kObscurance) {
    auto pass = profiler.pass(kAmbientPass);
    drawView(frame.target, true, offset);
    return;
  }
  surface_lighting_->lighting().setLightOffset(offset);
  surface_lighting_->render(*scene_, frame.target, profiler);
  {
    auto pass = profiler.pass(kAmbientPass);
    drawView(*ambient_view_, false, offset);
  }
  auto pass = profiler.pass(kObscuranceCompositePass);
  frame.target.bind();
  const gl::PipelineScope adding({.blend = gl::kAdditiveBlend});
  ambient_view_->color().bind(gpu::kAddedImageUnit);
  composite_pass_.draw();
}

std::vector<glm::vec3> ObscurancesTechnique::obscuranceMap() const {
  return atlas::atlasTexelValues(gl::readTexture(obscurance_, 3));
}

// Book Fig. 10.9: the first layers of a bundle along the camera's view, side by side in rows of
// three (the book's figure looks into the Cornell box from the front).
image::Image ObscurancesTechnique::peelLayersFigure() {
  const scene::Camera& camera = scene_->scene().camera;
  PeelBundle bundle;
  bundle.direction = glm::normalize(camera.look_at - camera.position);
  bundle.up = camera.up;
  const int layers = peeler_->peel(*mesh_, bundle);
  const int n = settings_.peel_resolution;
  const int columns = 3, rows = (kFigureLayers + columns - 1) / columns;
  image::Image figure(columns * n, rows * n);
  for (int k = 0; k < std::min(layers, kFigureLayers); ++k) {
    const image::Image layer = peeler_->layerDepthImage(k);
    const int x0 = (k % columns) * n, y0 = (k / columns) * n;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        for (int c = 0; c < 3; ++c) figure.pixel(x0 + x, y0 + y)[c] = layer.pixel(x, y)[c];
  }
  return figure;
}

std::vector<AuxiliaryImage> ObscurancesTechnique::auxiliaryImages() {
  std::vector<AuxiliaryImage> images;
  RenderTarget view(width_, height_);
  drawView(view, true, last_light_offset_);
  const std::string what = std::string(scene::describeObscurance(settings_.definition)) + " from " +
                           std::to_string(settings_.directions) + " bundles";
  images.push_back({"obscurance", "W seen by the camera: " + what, view.read()});
  images.push_back({"atlas", "the obscurances map, W per atlas texel: " + what,
                    gl::readTexture(obscurance_, 3)});
  if (ambient_view_)
    images.push_back({"ambient", "the ambient term Lᵃ·a·W seen by the camera (the indirect light)",
                      ambient_view_->read()});
  images.push_back({"peel-layers",
                    "depth-peeling layers 1–6 (left to right, top to bottom) of the bundle along "
                    "the camera's view; near white, far dark, empty black (book Fig. 10.9)",
                    peelLayersFigure()});
  return images;
}

std::vector<TechniqueStatistic> ObscurancesTechnique::statistics() const {
  return {{"directions", double(settings_.directions)},
          {"layers_mean", build_.layers_mean},
          {"layers_max", double(build_.layers_max)},
          {"layers_truncated", double(build_.layers_truncated)},
          {"peel_pixel_size", peeler_ ? double(peeler_->pixelSize()) : 0.0},
          {"d_max", double(d_max_)},
          {"ambient_luminance", double(scene::luminance(ambient_))},
          {"atlas_texels", double(texels_.covered)},
          {"prepare_peel_ms", build_.peel_ms},
          {"prepare_accumulate_ms", build_.accumulate_ms},
          {"prepare_normalize_ms", build_.normalize_ms}};
}

TechniqueInfo obscurancesTechniqueInfo() {
  TechniqueInfo info;
  info.name = "obscurances";
  info.description =
      "fake GI: direct light plus Lᵃ·a·W, scalar or spectral obscurances W from global ray "
      "bundles by depth peeling into an atlas";
  info.source =
      "Szirmay-Kalos et al., GPU-Based Techniques for Global Illumination Effects, Ch. 10";
  info.parameters = joinParameterTables(
      {{
           choiceParameter("mode", "spectral", {"scalar", "spectral"},
                           "scalar: W of eq. 10.2, grey; spectral: weighted by the albedo seen "
                           "(eq. 10.4), colour bleeding"),
           choiceParameter("falloff", "sqrt", {"sqrt", "ambient_occlusion"},
                           "ρ(d): the book's √(d/d_max), or ambient occlusion's step at d_max"),
           // The default is ObscuranceDefinition's (a test compares them).
           numericParameter("d_max", ParameterType::kNumber, "0.25", 1e-3, 100, "× diagonal",
                            "the neighbourhood d_max as a fraction of the scene's bounding-box "
                            "diagonal"),
           numericParameter("directions", ParameterType::kInteger, "64", 1, 65536, "",
                            "global ray bundles (uniformly distributed directions)"),
           numericParameter("peel_resolution", ParameterType::kInteger, "256", 8, 4096, "pixels",
                            "rays per side of a bundle (the orthographic view peeled)"),
           numericParameter("max_layers", ParameterType::kInteger, "16", 1, 64, "",
                            "layers peeled per bundle at most (surfaces a ray can cross; the "
                            "chamber's rays cross up to 13)"),
           atlasParameter(128, "obscurances map (atlas) texels per side"),
           choiceParameter("light_weighting", "none", {"none", "distance"},
                           "distance: the ambient term weighted by the inverse squared distance "
                           "to the lights (Fig. 10.6; README)"),
           choiceParameter("motion", "none", {"none", "light"},
                           "light: the lights move every frame (a circle, at rest on the last "
                           "frame); the map is not rebuilt"),
           choiceParameter("output", "final", {"final", "obscurance"},
                           "final: direct + ambient term; obscurance: W itself, measured against "
                           "the reference's obscurance"),
           seedParameter("the bundles' rotation and grid shifts, the same every run"),
       },
       SurfaceLighting::parameters()});
  PassDeclarations& passes = info.passes;
  SurfaceLighting::declarePasses(passes);
  passes.add(passPath({kFramePass, kAmbientPass}),
             "the camera view of the obscurances map: Lᵃ·a·W, or W for output=obscurance");
  passes.add(passPath({kFramePass, kObscuranceCompositePass}),
             "the ambient term added into the frame");
  info.auxiliary_images = {
      {"obscurance", "W seen by the camera"},
      {"atlas", "the obscurances map, W per atlas texel"},
      {"ambient", "the ambient term seen by the camera (output=final)"},
      {"peel-layers",
       "the first six depth-peeling layers of the bundle along the camera's view (book Fig. 10.9)"},
  };
  info.statistics = {
      {"directions", "global ray bundles traced"},
      {"layers_mean", "layers peeled per bundle, mean"},
      {"layers_max", "layers peeled per bundle, most"},
      {"layers_truncated", "bundles that reached max_layers"},
      {"peel_pixel_size", "distance between a bundle's rays, scene units"},
      {"d_max", "d_max in scene units"},
      {"ambient_luminance", "luminance of the ambient light Lᵃ"},
      {"atlas_texels", "atlas texels covered by a surface"},
      {"prepare_peel_ms", "map construction: depth peeling, all bundles"},
      {"prepare_accumulate_ms", "map construction: samples added into the atlas"},
      {"prepare_normalize_ms", "map construction: the normalisation pass"},
  };
  info.create = [](const ParameterValues& values) -> std::unique_ptr<Technique> {
    return std::make_unique<ObscurancesTechnique>(values);
  };
  return info;
}

}  // namespace gib::rt
