#include "realtime/techniques/light_path_map/light_path_map_technique.h"

#include "common/elapsed.h"
#include "common/input_error.h"
#include "common/luminance_shared.h"
#include "realtime/atlas/atlas_lighting.h"
#include "realtime/gl/finished_time.h"
#include "realtime/gl/gpu_commands.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/pipeline_state.h"
#include "realtime/gl/shader_library.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/technique_parameters.h"
#include "realtime/techniques/light_path_map/light_path_map_shared.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <numeric>

namespace gib::rt {

namespace {

LightPathMapSettings settingsFrom(const ParameterValues& p) {
  LightPathMapSettings s;
  s.entry_points = p.integer("entry_points");
  s.paths_per_entry = p.integer("paths_per_entry");
  s.clusters = p.integer("clusters");
  s.kmeans = p.text("clustering") == "kmeans";
  s.panes_used = p.integer("panes_used");
  s.atlas_resolution = p.integer("atlas");
  s.vpl_shadow_map_size = p.integer("vpl_shadow_map_size");
  s.moving_light = p.text("motion") == "light";
  s.indirect_only = p.text("output") == "indirect";
  s.seed = std::uint32_t(p.integer("seed"));
  s.shadow = shadowSettings(p);
  s.light_samples = p.integer("light_samples");
  return s;
}

void checkSettings(const LightPathMapSettings& s) {
  if (s.clusters > s.entry_points)
    throw InputError(fmt::format(
        "technique 'light_path_map': clusters={} exceeds entry_points={}; give at most one "
        "cluster per entry point",
        s.clusters, s.entry_points));
  if (s.panes_used > s.clusters)
    throw InputError(fmt::format(
        "technique 'light_path_map': panes_used={} exceeds clusters={}; give at most the "
        "cluster count",
        s.panes_used, s.clusters));
}

// Lloyd's iterations of clustering=kmeans, at most (it stops when no point moves).
constexpr int kKMeansIterations = 20;

double luminanceOf(const glm::vec3& c) {
  return kLuminanceRed * c.r + kLuminanceGreen * c.g + kLuminanceBlue * c.b;
}

// Bytes of level 0 of `texture` as GL reports its size and component sizes.
std::int64_t allocatedBytes(const gl::Texture& texture) {
  GLint bits = 0;
  for (GLenum component :
       {GL_TEXTURE_RED_SIZE, GL_TEXTURE_GREEN_SIZE, GL_TEXTURE_BLUE_SIZE, GL_TEXTURE_ALPHA_SIZE}) {
    GLint size = 0;
    glGetTextureLevelParameteriv(texture.id(), 0, component, &size);
    bits += size;
  }
  return std::int64_t(texture.width()) * texture.height() * texture.depth() * bits / 8;
}

}  // namespace

LightPathMapTechnique::LightPathMapTechnique(const ParameterValues& parameters)
    : LightPathMapTechnique(settingsFrom(parameters)) {}

LightPathMapTechnique::LightPathMapTechnique(const LightPathMapSettings& settings)
    : settings_(settings) {
  checkSettings(settings_);
}

scene::PathClass LightPathMapTechnique::pathClass() const {
  // The maps carry the paths from an entry point's reflection on (light, entry point, exit point,
  // eye: two bounces and more); the full image adds emission and the direct light.
  return {settings_.indirect_only ? 2 : 0, scene::PathClass::kUnlimited};
}

void LightPathMapTechnique::prepare(const GpuScene& scene, int width, int height) {
  scene_ = &scene;
  width_ = width;
  height_ = height;
  const int r = settings_.atlas_resolution;
  dots_vertex_array_.emplace();

  // The atlas: its texels are the exit points.
  triangles_ = atlas::atlasTriangles(scene.scene());
  const atlas::AtlasLayout layout = atlas::layoutAtlas(triangles_, r);
  texels_ = atlas::bakeAtlasTexels(triangles_, layout);
  texel_side_ = layout.texels_per_unit > 0 ? 1.0f / layout.texels_per_unit : 0.0f;
  atlas_.emplace(texels_, triangles_, scene.scene());
  mesh_.emplace(triangles_, layout, 0);

  // Preprocessing, the book's three stages: the ray caster's acceleration structure, light
  // tracing on the CPU, the panes on the GPU.
  auto start = std::chrono::steady_clock::now();
  const std::unique_ptr<scene::RayCaster> caster = services_.ray_caster(scene.scene());
  preprocessing_.ray_caster_ms = millisecondsSince(start);

  start = std::chrono::steady_clock::now();
  double total_area = 0;
  for (const atlas::AtlasTriangle& t : triangles_) total_area += t.area;
  entries_ = lpm::sampleEntryPoints(triangles_, settings_.entry_points, settings_.seed);
  cluster_of_entry_ = settings_.kmeans ? lpm::clusterEntryPointsKMeans(entries_, settings_.clusters,
                                                                       kKMeansIterations)
                                       : lpm::clusterEntryPoints(entries_, settings_.clusters);
  const lpm::LightWalks walks = lpm::traceLightWalks(
      *caster, scene.scene(), triangles_, entries_, cluster_of_entry_, settings_.paths_per_entry,
      total_area, settings_.seed, settings_.max_walk_vertices);
  preprocessing_.light_tracing_ms = millisecondsSince(start);
  preprocessing_.path_vertices = walks.path_vertices;
  preprocessing_.virtual_lights = walks.lights.size();
  cluster_size_.assign(std::size_t(settings_.clusters), 0);
  for (int c : cluster_of_entry_) ++cluster_size_[std::size_t(c)];

  preprocessing_.lpm_ms = gl::finishedMilliseconds([&] { buildPanes(walks); });
  preprocessing_.pane_bytes = allocatedBytes(panes_);

  // What a frame needs.
  surface_lighting_.emplace(settings_.shadow, settings_.light_samples);
  surface_lighting_->prepare(scene, width, height);
  indirect_view_.emplace(width, height);
  uploadEntryPoints();
  indirect_ = gl::Texture::make2D(GL_RGBA32F, r, r);
  indirect_framebuffer_.attachColor(0, indirect_);
  indirect_framebuffer_.setDrawBuffers(1);
  indirect_framebuffer_.checkComplete();
  combine_pass_ = gl::FullScreenPass("realtime/techniques/light_path_map/combine.frag.glsl");
  composite_pass_ = gl::FullScreenPass("realtime/gl/add_image.frag.glsl");
  view_program_ =
      gl::buildProgram({{GL_VERTEX_SHADER, "realtime/atlas/atlas_view.vert.glsl"},
                        {GL_FRAGMENT_SHADER, "realtime/techniques/light_path_map/view.frag.glsl"}});
  entry_dots_program_ = gl::buildProgram(
      {{GL_VERTEX_SHADER, "realtime/techniques/light_path_map/entry_points.vert.glsl"},
       {GL_FRAGMENT_SHADER, "realtime/techniques/light_path_map/entry_points.frag.glsl"}});
}

// Every virtual light's shadow map, then its light reflected by every exit texel it sees, added
// into its cluster's pane: the lights come sorted by cluster, so one cluster at a time is summed
// in a float target and then stored in its layer of the half-float pane array (the book's
// 128 MB for 256 panes of 256²).
void LightPathMapTechnique::buildPanes(const lpm::LightWalks& walks) {
  const int r = settings_.atlas_resolution;
  panes_ = gl::Texture::make2DArray(GL_RGBA16F, r, r, settings_.clusters);
  gl::Texture sum = gl::Texture::make2D(GL_RGBA32F, r, r);
  gl::Framebuffer sum_framebuffer, pane_framebuffer;
  sum_framebuffer.attachColor(0, sum);
  sum_framebuffer.setDrawBuffers(1);
  sum_framebuffer.checkComplete();

  ShadowSettings shadow;
  shadow.filter = ShadowFilter::kHard;
  shadow.size = settings_.vpl_shadow_map_size;
  // A cluster's virtual lights go in batches; no cluster holds more than this many.
  std::size_t largest_cluster = 0, run = 0;
  for (std::size_t i = 0; i < walks.lights.size(); ++i) {
    const bool same = i > 0 && walks.lights[i].cluster == walks.lights[i - 1].cluster;
    run = same ? run + 1 : 1;
    largest_cluster = std::max(largest_cluster, run);
  }
  atlas::AtlasLighting lighting(shadow, *scene_, largest_cluster);
  // A virtual light stands for the patch around its point, about a texel of the atlas: its light
  // on a texel beside it is that of a disk of a texel's area (light_irradiance.glsl).
  const float distance_offset = texel_side_ * texel_side_ * std::numbers::inv_pi_v<float>;
  const float lift = 1e-3f * glm::length(scene_->boundsMax() - scene_->boundsMin());
  const float zero[4] = {0, 0, 0, 0};
  std::size_t next = 0;
  std::vector<LightSample> cluster_lights;
  for (int c = 0; c < settings_.clusters; ++c) {
    glClearTexImage(sum.id(), 0, GL_RGBA, GL_FLOAT, zero);
    cluster_lights.clear();
    for (; next < walks.lights.size() && walks.lights[next].cluster == c; ++next) {
      const lpm::VirtualLight& v = walks.lights[next];
      LightSample sample;
      sample.kind = LightSampleKind::kPoint;
      sample.position = v.position + lift * v.normal;
      sample.axis = v.normal;
      sample.intensity = v.intensity;
      sample.cos_cone = 0.0f;
      sample.exponent = 1.0f;
      sample.distance_squared_offset = distance_offset;
      cluster_lights.push_back(sample);
    }
    lighting.add(*scene_, cluster_lights, *atlas_, sum_framebuffer);
    pane_framebuffer.attachColor(0, panes_, 0, c);
    glBlitNamedFramebuffer(sum_framebuffer.id(), pane_framebuffer.id(), 0, 0, r, r, 0, 0, r, r,
                           GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
}

// The entry points as texels of a square texture (point i at (i mod side, i div side)), and the
// target their irradiance is added into.
void LightPathMapTechnique::uploadEntryPoints() {
  const int n = int(entries_.size());
  entry_side_ = std::max(1, int(std::ceil(std::sqrt(double(n)))));
  const std::size_t texels = std::size_t(entry_side_) * std::size_t(entry_side_);
  std::vector<glm::vec4> position(texels, glm::vec4(0.0f)), normal(texels, glm::vec4(0.0f));
  for (int i = 0; i < n; ++i) {
    position[std::size_t(i)] = glm::vec4(entries_[std::size_t(i)].position, 1.0f);
    normal[std::size_t(i)] = glm::vec4(entries_[std::size_t(i)].normal, 0.0f);
  }
  entry_position_ = gl::Texture::make2D(GL_RGBA32F, entry_side_, entry_side_);
  entry_position_.upload(&position[0].x, GL_RGBA);
  entry_normal_ = gl::Texture::make2D(GL_RGBA32F, entry_side_, entry_side_);
  entry_normal_.upload(&normal[0].x, GL_RGBA);
  entry_irradiance_texture_ = gl::Texture::make2D(GL_RGBA32F, entry_side_, entry_side_);
  entry_framebuffer_.attachColor(0, entry_irradiance_texture_);
  entry_framebuffer_.setDrawBuffers(1);
  entry_framebuffer_.checkComplete();
  const ShadowMaps& maps = surface_lighting_->lighting().shadowMaps();
  auto pass = [&](LightSampleKind kind) {
    gl::FullScreenPass p("realtime/techniques/light_path_map/entry_irradiance.frag.glsl",
                         maps.defines(kind));
    maps.setLookupConstants(p.program());
    return p;
  };
  entry_point_pass_ = pass(LightSampleKind::kPoint);
  entry_directional_pass_ = pass(LightSampleKind::kDirectional);
}

void LightPathMapTechnique::render(Frame& frame) {
  gl::PassProfiler& profiler = frame.profiler;
  surface_lighting_->lighting().setLightOffset(
      settings_.moving_light ? movingLightOffset(*scene_, frame) : fixed_light_offset_);
  const float zero[4] = {0, 0, 0, 0};
  glClearTexImage(entry_irradiance_texture_.id(), 0, GL_RGBA, GL_FLOAT, zero);
  const auto weigh = [&](const ShadowMaps& maps) {
    auto pass = profiler.pass(kEntryIrradiancePass);
    const gl::FullScreenPass& p =
        maps.batchKind() == LightSampleKind::kPoint ? entry_point_pass_ : entry_directional_pass_;
    p.use();
    maps.bindForLookup(p.program());
    entry_position_.bind(gpu::kEntryPositionUnit);
    entry_normal_.bind(gpu::kEntryNormalUnit);
    entry_framebuffer_.bind();
    const gl::PipelineScope adding({
        .blend = gl::kAdditiveBlend,
        .viewport = gl::PixelRect{0, 0, entry_side_, entry_side_},
    });
    p.draw();
  };
  // output=indirect weighs the panes by the direct light without drawing it.
  const RenderTarget* camera = nullptr;
  if (!settings_.indirect_only) {
    surface_lighting_->drawSurfaces(*scene_, frame.target, profiler);
    camera = &frame.target;
  }
  surface_lighting_->addDirect(*scene_, camera, profiler, {}, weigh);
  renderIndirect(profiler);
  auto pass = profiler.pass(kCompositePass);
  frame.target.bind();
  const gl::PipelineScope adding({.blend = gl::kAdditiveBlend});
  indirect_view_->color().bind(gpu::kAddedImageUnit);
  composite_pass_.draw();
}

// The clusters' weights from the entry points' irradiance (read back, as the book does, to choose
// the panes on the CPU), the highest `panes_used` uploaded. A cluster's contribution is its weight
// times its pane, the sum of its members' panes; with clusters equally large (the kd-tree's, to
// within one point) ranking by weight × members is the book's ranking by weight.
void LightPathMapTechnique::selectPanes() {
  const image::Image irradiance = gl::readTexture(entry_irradiance_texture_, 3);
  const std::size_t n = entries_.size();
  entry_irradiance_.assign(n, glm::vec3(0.0f));
  for (std::size_t i = 0; i < n; ++i) {  // readTexture's rows run top to bottom
    const int x = int(i) % entry_side_, y = int(i) / entry_side_;
    const float* v = irradiance.pixel(x, entry_side_ - 1 - y);
    entry_irradiance_[i] = {v[0], v[1], v[2]};
  }
  cluster_weights_.assign(std::size_t(settings_.clusters), glm::vec3(0.0f));
  for (std::size_t i = 0; i < n; ++i)
    cluster_weights_[std::size_t(cluster_of_entry_[i])] += entry_irradiance_[i];
  for (std::size_t c = 0; c < cluster_weights_.size(); ++c)
    cluster_weights_[c] /= float(std::max(cluster_size_[c], 1));
  std::vector<int> order(cluster_weights_.size());
  std::iota(order.begin(), order.end(), 0);
  const auto importance = [&](int c) {
    return luminanceOf(cluster_weights_[std::size_t(c)]) * cluster_size_[std::size_t(c)];
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return importance(a) > importance(b); });
  std::vector<gpu::SelectedPane> selected;
  for (int c : order) {
    if (int(selected.size()) == settings_.panes_used || importance(c) <= 0) break;
    selected.push_back({cluster_weights_[std::size_t(c)] / float(n), c});
  }
  selected_count_ = int(selected.size());
  // A frame's panes, a round of their own (at least one record, so that the range bound for
  // a frame without any is not empty).
  selected_bytes_ = std::max<std::size_t>(selected.size(), 1) * sizeof(gpu::SelectedPane);
  selected_panes_.beginRound({selected_bytes_});
  selected_offset_ = selected_panes_.push(selected, selected_bytes_);
}

void LightPathMapTechnique::renderIndirect(gl::PassProfiler& profiler) {
  {
    auto pass = profiler.pass(kPaneSelectionPass);
    selectPanes();
  }
  {
    auto pass = profiler.pass(kIndirectAtlasPass);
    const int r = settings_.atlas_resolution;
    indirect_framebuffer_.bind();
    const gl::PipelineScope state({.viewport = gl::PixelRect{0, 0, r, r}});
    combine_pass_.program().set("u_selected_count", selected_count_);
    panes_.bind(gpu::kPanesUnit);
    selected_panes_.bindRange(GL_SHADER_STORAGE_BUFFER, gpu::kSelectedPanesBinding,
                              selected_offset_, selected_bytes_);
    combine_pass_.draw();
  }
  auto pass = profiler.pass(kIndirectViewPass);
  indirect_view_->clear(0, 0, 0);
  indirect_view_->bind();
  const gl::PipelineScope state({.depth_test = GL_LESS});
  view_program_.use();
  view_program_.set("u_show_albedo", 0);
  scene_->bindSceneBuffers();
  atlas_->bind();
  indirect_.bind(gpu::kIndirectUnit);
  mesh_->draw();
}

std::vector<glm::vec3> LightPathMapTechnique::pane(int cluster) const {
  const int r = settings_.atlas_resolution;
  std::vector<float> values(std::size_t(r) * std::size_t(r) * 4);
  glGetTextureSubImage(panes_.id(), 0, 0, 0, cluster, r, r, 1, GL_RGBA, GL_FLOAT,
                       GLsizei(values.size() * sizeof(float)), values.data());
  std::vector<glm::vec3> texels(std::size_t(r) * std::size_t(r));
  for (std::size_t i = 0; i < texels.size(); ++i)
    texels[i] = {values[4 * i], values[4 * i + 1], values[4 * i + 2]};
  return texels;
}

std::vector<AuxiliaryImage> LightPathMapTechnique::auxiliaryImages() {
  std::vector<AuxiliaryImage> images;
  const image::Image indirect = indirect_view_->read();
  images.push_back({"indirect",
                    "the light path map's indirect light seen by the camera (two or more bounces), "
                    "from the " +
                        std::to_string(selected_count_) + " highest-weighted of " +
                        std::to_string(settings_.clusters) + " cluster panes",
                    indirect});

  // Book Fig. 8.12: the entry points over the scene.
  RenderTarget dots(width_, height_);
  dots.clear(0, 0, 0);
  dots.bind();
  {
    // The dots on the surfaces they lie on pass the depth test.
    const gl::PipelineScope state({.depth_test = GL_LEQUAL, .program_point_size = true});
    view_program_.use();
    view_program_.set("u_show_albedo", 1);
    scene_->bindSceneBuffers();
    atlas_->bind();
    mesh_->draw();
    entry_dots_program_.use();
    entry_dots_program_.set("u_lift",
                            2e-3f * glm::length(scene_->boundsMax() - scene_->boundsMin()));
    // A dot of a pixel per 320 of width: the book's figure's density at any size.
    entry_dots_program_.set("u_point_size", std::max(1.0f, std::round(float(width_) / 320.0f)));
    entry_position_.bind(gpu::kEntryPositionUnit);
    entry_normal_.bind(gpu::kEntryNormalUnit);
    dots_vertex_array_->bind();
    gl::drawArrays(GL_POINTS, 0, GLsizei(entries_.size()));
  }
  images.push_back(
      {"entry-points",
       std::to_string(entries_.size()) + " entry points over the scene (book Fig. 8.12)",
       dots.read()});

  images.push_back({"atlas", "indirect exit radiance per atlas texel (exit point)",
                    gl::readTexture(indirect_, 3)});

  if (!settings_.indirect_only) {
    // Book Fig. 8.13: local illumination below, with the light path map above.
    RenderTarget direct(width_, height_);
    direct.clear(0, 0, 0);
    gl::PassProfiler untimed;
    surface_lighting_->render(*scene_, direct, untimed);
    image::Image split = direct.read();
    for (int y = 0; y < height_ / 2; ++y)
      for (int x = 0; x < width_; ++x)
        for (int k = 0; k < 3; ++k) split.pixel(x, y)[k] += indirect.pixel(x, y)[k];
    images.push_back({"local-and-lpm",
                      "upper half: direct + light path map; lower half: local (direct) "
                      "illumination alone (book Fig. 8.13)",
                      split});
  }
  return images;
}

std::vector<TechniqueStatistic> LightPathMapTechnique::statistics() const {
  return {{"entry_points", double(entries_.size())},
          {"clusters", double(settings_.clusters)},
          {"virtual_lights", double(preprocessing_.path_vertices)},
          {"vpl_shadow_maps", double(preprocessing_.virtual_lights)},
          {"pane_memory_mb", double(preprocessing_.pane_bytes) / (1024.0 * 1024.0)},
          {"prepare_ray_caster_ms", preprocessing_.ray_caster_ms},
          {"prepare_light_tracing_ms", preprocessing_.light_tracing_ms},
          {"prepare_lpm_ms", preprocessing_.lpm_ms},
          {"atlas_texels", double(texels_.covered)}};
}

TechniqueInfo lightPathMapTechniqueInfo() {
  TechniqueInfo info;
  info.name = "light_path_map";
  info.description =
      "direct light (shadow maps) plus indirect light (L D D+ E, diffuse) from light path maps: "
      "precomputed per entry-point cluster, weighted by the current lights every frame; "
      "output=indirect for the maps' own paths";
  info.source = "Szirmay-Kalos et al., GPU-Based Techniques for Global Illumination Effects, §8.4";
  info.parameters = joinParameterTables(
      {{
           numericParameter(
               "entry_points", ParameterType::kInteger, "4096", 1, 65536, "",
               "entry points sampled uniformly over the surface area (the book's 4096)"),
           numericParameter("paths_per_entry", ParameterType::kInteger, "2", 1, 64, "",
                            "random walks started from each entry point (the book's 2)"),
           numericParameter(
               "clusters", ParameterType::kInteger, "256", 1, 2048, "",
               "entry-point clusters by object-median kd-tree, one pane each (the book's "
               "256); at most entry_points"),
           choiceParameter(
               "clustering", "kdtree", {"kdtree", "kmeans"},
               "entry-point clusters: object-median kd-tree (equal sizes), or K-means from "
               "it over position and normal (the book's alternative)"),
           numericParameter(
               "panes_used", ParameterType::kInteger, "32", 1, 2048, "",
               "highest-weighted cluster panes summed per frame (the book's 32); at most "
               "clusters"),
           atlasParameter(256, "pane (atlas) resolution: exit points per side (the book's 256)"),
           numericParameter(
               "vpl_shadow_map_size", ParameterType::kInteger, "256", 16, 2048, "texels",
               "shadow map of each virtual light, per cube face, while the panes are built"),
           choiceParameter(
               "motion", "none", {"none", "light"},
               "light: the lights move every frame (a circle, at rest on the last frame); "
               "the maps are not rebuilt"),
           choiceParameter(
               "output", "full", {"full", "indirect"},
               "full: emission + direct + indirect; indirect: the maps' paths alone (two or "
               "more bounces)"),
           seedParameter("entry points and random walks, the same every run"),
       },
       SurfaceLighting::parameters()});
  PassDeclarations& passes = info.passes;
  SurfaceLighting::declarePasses(
      passes, {{kEntryIrradiancePass, "the light sample's irradiance at every entry point"}});
  passes.add(passPath({kFramePass, kPaneSelectionPass}),
             "entry irradiance read back; cluster weights; the highest-weighted panes chosen");
  passes.add(passPath({kFramePass, kIndirectAtlasPass}),
             "every exit texel: the chosen panes weighted and summed");
  passes.add(passPath({kFramePass, kIndirectViewPass}),
             "the camera view of the indirect atlas, bilinear");
  passes.add(passPath({kFramePass, kCompositePass}), "the indirect light added into the frame");
  info.auxiliary_images = {
      {"indirect", "the light path map's indirect light seen by the camera (two or more bounces)"},
      {"entry-points", "the entry points over the scene (book Fig. 8.12)"},
      {"atlas", "indirect exit radiance per atlas texel (exit point)"},
      {"local-and-lpm",
       "upper half: direct + light path map; lower half: local illumination alone (book Fig. "
       "8.13)"},
  };
  info.statistics = {
      {"entry_points", "entry points sampled over the surfaces"},
      {"clusters", "entry-point clusters, one pane each"},
      {"virtual_lights", "path vertices of the random walks (virtual lights)"},
      {"vpl_shadow_maps", "virtual lights rendered with a shadow map"},
      {"pane_memory_mb", "memory of the panes"},
      {"prepare_ray_caster_ms", "time to build the ray caster's BVH"},
      {"prepare_light_tracing_ms", "time to trace the random walks"},
      {"prepare_lpm_ms", "time to build the light path maps"},
      {"atlas_texels", "atlas texels covered by a surface"},
  };
  info.needs = {TechniqueNeed::kRayCaster};
  info.create = [](const ParameterValues& values) -> std::unique_ptr<Technique> {
    return std::make_unique<LightPathMapTechnique>(values);
  };
  return info;
}

}  // namespace gib::rt
