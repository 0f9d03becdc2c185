#include "realtime/techniques/prt/prt_technique.h"

#include "common/elapsed.h"
#include "common/input_error.h"
#include "realtime/gl/gpu_commands.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/pipeline_state.h"
#include "realtime/gl/shader_library.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/lighting/environment_texture.h"
#include "realtime/render_target.h"
#include "realtime/sh/sh_basis.h"
#include "realtime/sh/sh_projection.h"
#include "realtime/technique_parameters.h"
#include "realtime/techniques/prt/prt_errors.h"
#include "realtime/techniques/prt/prt_projection.h"
#include "realtime/techniques/prt/prt_shared.h"
#include "realtime/techniques/prt/prt_transfer.h"
#include "scene/path_expression.h"
#include "scene/scene.h"

#include <fmt/format.h>
#include <glm/trigonometric.hpp>

#include <chrono>
#include <memory>
#include <numeric>
#include <string>

namespace gib::rt {

namespace {

// More vertices than this is a max_edge far too small for the scene (the outdoor ground is 100 m
// across): refused before minutes of ray casting.
constexpr std::size_t kMaxVertices = 2'000'000;

PrtSettings settingsFrom(const ParameterValues& p) {
  PrtSettings s;
  s.bands = p.integer("sh_bands");
  s.rays = p.integer("rays");
  s.bounces = p.integer("bounces");
  s.compress = p.text("compression") == "cpca";
  s.clusters = p.integer("clusters");
  s.pca_vectors = p.integer("pca_vectors");
  s.max_edge = float(p.number("max_edge"));
  s.light_rotation_deg = float(p.number("light_rotation_deg"));
  s.seed = std::uint32_t(p.integer("seed"));
  return s;
}

void checkSettings(const PrtSettings& s) {
  sh::checkShBands(s.bands);
  // The RGB vectors are compressed together (README.md, "Compression"): 3·bands² dimensions.
  const int dimension = 3 * sh::shBasisCount(s.bands);
  // compression=none keeps every vector whole and reads no basis.
  if (s.compress && s.pca_vectors > dimension)
    throw InputError(fmt::format(
        "technique 'prt': pca_vectors={} exceeds the transfer vectors' dimension 3·sh_bands² = "
        "{} (sh_bands={}); give at most {}",
        s.pca_vectors, dimension, s.bands, dimension));
}

// compression=none: every vertex its own cluster, whose mean is its vector (no basis).
prt::CpcaResult uncompressed(const std::vector<float>& vectors, int dimension) {
  prt::CpcaResult result;
  result.dimension = dimension;
  result.pca_vectors = 0;
  result.clusters = int(vectors.size() / std::size_t(dimension));
  result.cluster.resize(std::size_t(result.clusters));
  std::iota(result.cluster.begin(), result.cluster.end(), 0);
  result.means = vectors;
  return result;
}

std::string pathExpression(int bounces) {
  return fmt::format("LD{{0,{}}}E", bounces);
}

}  // namespace

PrtTechnique::PrtTechnique(const ParameterValues& parameters)
    : settings_(settingsFrom(parameters)), surface_lighting_(parameters) {
  checkSettings(settings_);
}

scene::PathClass PrtTechnique::pathClass() const {
  return scene::PathClass::ofExpression(
      scene::PathExpression::parse(pathExpression(settings_.bounces)).text());
}

void PrtTechnique::prepare(const GpuScene& scene, int width, int height) {
  scene_ = &scene;
  // The environment's light is the transfer's (and spot and area lights SurfaceLighting's).
  surface_lighting_.lighting().setEnvironmentSamples(false);
  surface_lighting_.prepare(scene, width, height);
  const EnvironmentTexture* texture = surface_lighting_.lighting().environment();
  // A constant sky is a constant map (2 × 1 texels).
  const scene::EnvironmentMap map = texture ? texture->map() : sceneEnvironment(scene.scene());

  auto start = std::chrono::steady_clock::now();
  lighting_ = sh::projectLatLong(map, settings_.bands);
  preprocessing_.projection_ms = millisecondsSince(start);
  preprocessing_.sh_truncation_error = prt::shTruncationError(map, lighting_, settings_.bands);

  mesh_ = prt::tessellate(scene.scene(), settings_.max_edge, kMaxVertices);

  start = std::chrono::steady_clock::now();
  const std::unique_ptr<scene::RayCaster> caster = services_.ray_caster(scene.scene());
  preprocessing_.ray_caster_ms = millisecondsSince(start);
  start = std::chrono::steady_clock::now();
  prt::TransferSettings transfer_settings;
  transfer_settings.bands = settings_.bands;
  transfer_settings.rays = settings_.rays;
  transfer_settings.bounces = settings_.bounces;
  transfer_settings.seed = settings_.seed;
  const prt::Transfer transfer =
      prt::computeTransfer(mesh_, scene.scene(), *caster, transfer_settings, lighting_);
  preprocessing_.transfer_ms = millisecondsSince(start);
  preprocessing_.rays_cast = transfer.rays_cast;
  preprocessing_.rays_hit = transfer.rays_hit;
  preprocessing_.monte_carlo_error = transfer.monte_carlo_error;

  start = std::chrono::steady_clock::now();
  compressed_ = settings_.compress
                    ? prt::compressCpca(transfer.vectors, transfer.dimension(), settings_.clusters,
                                        settings_.pca_vectors, settings_.seed)
                    : uncompressed(transfer.vectors, transfer.dimension());
  preprocessing_.compression_ms = millisecondsSince(start);
  preprocessing_.cpca_error = prt::cpcaRelativeError(transfer.vectors, compressed_);
  // The same error in what is seen: the vertices' radiance under the scene's own lighting.
  preprocessing_.cpca_radiance_error = prt::relativeSquaredError(
      prt::vertexRadiance(transfer.vectors, transfer.coefficients, lighting_),
      prt::vertexRadiance(prt::reconstruct(compressed_), transfer.coefficients, lighting_));

  // The GPU side: the vertices and their compressed vectors' weights; the projections per frame.
  std::vector<glm::vec4> positions;
  positions.reserve(mesh_.vertexCount());
  for (const glm::vec3& p : mesh_.positions) positions.emplace_back(p, 1.0f);
  positions_ = gl::Buffer::fromVector(positions);
  corners_ = gl::Buffer::fromVector(mesh_.corners);
  std::vector<std::uint32_t> clusters(compressed_.cluster.begin(), compressed_.cluster.end());
  clusters_ = gl::Buffer::fromVector(clusters);
  // A storage buffer may not be empty: one unread weight when M = 0.
  std::vector<float> weights = compressed_.weights;
  if (weights.empty()) weights.push_back(0.0f);
  weights_ = gl::Buffer::fromVector(weights);
  projections_.assign(std::size_t(compressed_.clusters) * std::size_t(compressed_.pca_vectors + 1),
                      glm::vec4(0.0f));
  projection_buffer_ = gl::Buffer::fromVector(projections_);
  empty_vertex_array_.emplace();
  program_ = gl::buildProgram({{GL_VERTEX_SHADER, "realtime/techniques/prt/prt.vert.glsl"},
                               {GL_FRAGMENT_SHADER, "realtime/techniques/prt/prt.frag.glsl"}});
  program_.use();
  program_.set("u_pca_vectors", compressed_.pca_vectors);
}

void PrtTechnique::render(Frame& frame) {
  surface_lighting_.render(*scene_, frame.target, frame.profiler);
  {
    auto pass = frame.profiler.pass(kLightProjectionPass);
    const auto start = std::chrono::steady_clock::now();
    // The light turns by light_rotation_deg each frame and is at rest, the scene's own, on the
    // last one (the measured image).
    prt::projectLighting(compressed_, lighting_, settings_.bands,
                         glm::radians(settings_.light_rotation_deg) * float(frame.frames_left),
                         rotated_, projections_);
    projection_buffer_.update(0, projections_.size() * sizeof(glm::vec4), projections_.data());
    projection_cpu_ms_ += millisecondsSince(start);
    ++frames_;
  }
  auto pass = frame.profiler.pass(kPrtVerticesPass);
  // The radiance is added to the emission and the scene's lights (zero on the surfaces PRT
  // shades), so only the nearest surface may be drawn at a pixel: the depth first, in the
  // target's own depth buffer, then the colour where the depth is equal (the same vertex shader,
  // gl_Position invariant).
  const float far_depth = 1.0f;
  glClearNamedFramebufferfv(frame.target.framebuffer().id(), GL_DEPTH, 0, &far_depth);
  frame.target.bind();
  program_.use();
  scene_->bindSceneBuffers();
  positions_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kPrtPositionsBinding);
  corners_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kPrtCornersBinding);
  clusters_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kPrtClustersBinding);
  weights_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kPrtWeightsBinding);
  projection_buffer_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kPrtProjectionsBinding);
  empty_vertex_array_->bind();
  const GLsizei corners = GLsizei(mesh_.corners.size());
  {
    const gl::PipelineScope depth(
        {.depth_test = GL_LESS, .color_write = {false, false, false, false}});
    gl::drawArrays(GL_TRIANGLES, 0, corners);
  }
  const gl::PipelineScope adding(
      {.depth_test = GL_EQUAL, .depth_write = false, .blend = gl::kAdditiveBlend});
  gl::drawArrays(GL_TRIANGLES, 0, corners);
}

std::vector<TechniqueStatistic> PrtTechnique::statistics() const {
  const PrtPreprocessing& p = preprocessing_;
  return {{"vertices", double(mesh_.vertexCount())},
          {"triangles", double(mesh_.triangleCount())},
          {"transfer_dimension", double(compressed_.dimension)},
          {"clusters", double(compressed_.clusters)},
          {"rays_cast", double(p.rays_cast)},
          {"hit_fraction", p.rays_cast > 0 ? double(p.rays_hit) / double(p.rays_cast) : 0.0},
          {"prepare_ray_caster_ms", p.ray_caster_ms},
          {"transfer_ms", p.transfer_ms},
          {"compression_ms", p.compression_ms},
          {"projection_ms", p.projection_ms},
          {"sh_truncation_error", p.sh_truncation_error},
          {"cpca_error", p.cpca_error},
          {"cpca_radiance_error", p.cpca_radiance_error},
          {"monte_carlo_error", p.monte_carlo_error}};
}

std::vector<TechniqueStatistic> PrtTechnique::finalStatistics() const {
  return {{"light_projection_cpu_ms", frames_ > 0 ? projection_cpu_ms_ / frames_ : 0.0}};
}

TechniqueInfo prtTechniqueInfo() {
  TechniqueInfo info;
  info.name = "prt";
  info.description =
      "diffuse pre-computed radiance transfer: per-vertex SH transfer vectors with shadows and "
      "interreflections by CPU ray casting, CPCA-compressed, lit by the environment's SH "
      "projection each frame (a Phong material's diffuse part only, its lobe ignored)";
  info.source =
      "Szirmay-Kalos et al., GPU-Based Techniques for Global Illumination Effects, §8.3 and "
      "Figs. 8.4-8.5";
  info.parameters = joinParameterTables(
      {{numericParameter("sh_bands", ParameterType::kInteger, "6", 1, sh::kShBasisMaxBands, "",
                         "spherical-harmonic bands n (n² coefficients per channel; the book's "
                         "\"order 6\" is 36)"),
        numericParameter("rays", ParameterType::kInteger, "256", 16, 65536, "",
                         "cosine-distributed, stratified rays per vertex (book: 1024)"),
        numericParameter("bounces", ParameterType::kInteger, "1", 1, 6, "",
                         "diffuse reflections in the transfer: 1 the shadowed direct light of the "
                         "environment, 6 the book's light paths of maximum length 6"),
        choiceParameter("compression", "cpca", {"cpca", "none"},
                        "cpca: clustered PCA of the transfer vectors (eq. 8.5); none: every "
                        "vertex keeps its own vector"),
        numericParameter("clusters", ParameterType::kInteger, "16", 1, 4096, "",
                         "CPCA clusters (at most the vertex count)"),
        numericParameter("pca_vectors", ParameterType::kInteger, "8", 0, 192, "",
                         "CPCA basis vectors per cluster, at most 3·sh_bands² (RGB compressed "
                         "together)"),
        numericParameter("max_edge", ParameterType::kNumber, "0.5", 1e-3, 1e3, "m",
                         "longest edge of the regular re-tessellation that carries the vertices"),
        numericParameter("light_rotation_deg", ParameterType::kNumber, "0", -360, 360, "degrees",
                         "turn of the lighting about +y per frame before the last "
                         "(the last frame is lit by the scene's own environment)"),
        seedParameter("seed of the rays and of CPCA's k-means++")},
       SurfaceLighting::parameters()});
  SurfaceLighting::declarePasses(info.passes);
  info.passes.add(passPath({kFramePass, kLightProjectionPass}),
                  "CPU: the lighting's SH rotation and its dot products with every cluster's "
                  "mean and basis vectors (eq. 8.5), uploaded");
  info.passes.add(passPath({kFramePass, kPrtVerticesPass}),
                  "the re-tessellated vertices, each summing its weighted dot products: a depth "
                  "pass, then the radiance added where the depth is equal");
  info.statistics = {
      {"vertices", "vertices of the re-tessellation, each with a transfer vector"},
      {"triangles", "sub-triangles drawn"},
      {"transfer_dimension", "floats per transfer vector: 3·sh_bands²"},
      {"clusters", "CPCA clusters (the vertex count for compression=none)"},
      {"rays_cast", "rays cast for the transfer (vertices × rays)"},
      {"hit_fraction", "share of the rays that met a surface"},
      {"prepare_ray_caster_ms", "time to build the ray caster's BVH"},
      {"transfer_ms", "time to compute the transfer vectors (ray casting and bounces)"},
      {"compression_ms", "time of CPCA"},
      {"projection_ms", "time to project the environment onto the SH basis"},
      {"sh_truncation_error",
       "relative squared L2 error of the environment's SH expansion over its texels"},
      {"cpca_error", "CPCA's relative squared error of the transfer vectors"},
      {"cpca_radiance_error",
       "CPCA's relative squared error of the vertices' radiance under the scene's lighting"},
      {"monte_carlo_error",
       "estimated relative standard error of the vertices' radiance from the rays' sample "
       "variance"},
      {"light_projection_cpu_ms", "CPU time per frame of the lighting's rotation and projection"}};
  info.needs = {TechniqueNeed::kEnvironmentLight, TechniqueNeed::kRayCaster};
  info.renders_environment_map = true;
  info.create = [](const ParameterValues& values) -> std::unique_ptr<Technique> {
    return std::make_unique<PrtTechnique>(values);
  };
  return info;
}

}  // namespace gib::rt
