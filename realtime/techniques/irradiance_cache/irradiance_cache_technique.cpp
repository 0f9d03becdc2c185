#include "realtime/techniques/irradiance_cache/irradiance_cache_technique.h"

#include "common/elapsed.h"
#include "common/input_error.h"
#include "common/parallel_for.h"
#include "common/splitmix.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gpu_scene/brdf_shared.h"
#include "realtime/irradiance_cache/irradiance_cache_parameters.h"
#include "realtime/irradiance_cache/zone_illustration.h"
#include "realtime/render_target.h"
#include "realtime/technique_parameters.h"
#include "realtime/techniques/irradiance_cache/ward_hemisphere.h"
#include "scene/camera.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <limits>

namespace gib::rt {

namespace {

constexpr std::string_view kSurfacesPass = "surfaces";
constexpr std::string_view kRecordsPass = "records";
constexpr std::string_view kInterpolationPass = "interpolation";
constexpr std::string_view kUploadPass = "upload";

using Clock = std::chrono::steady_clock;

// Uniform numbers in [0, 1) of one record's own stream (SplitMix64 of a counter).
class RecordRandom {
 public:
  explicit RecordRandom(std::uint64_t key) : state_(key) {}
  float next() { return float(splitMix64(state_ += kGoldenGamma) >> 40) * 0x1p-24f; }

 private:
  std::uint64_t state_;
};

}  // namespace

// The triangle a ray met: its unit geometric normal and its material, from a table made once
// (computing the normal from the mesh's vertices at every hit cost a tenth of the frame).
IrradianceCacheTechnique::SurfaceHit IrradianceCacheTechnique::surfaceHit(
    const scene::RayHit& hit) const {
  const glm::vec4& t = triangles_[mesh_offsets_[hit.mesh] + hit.triangle];
  return {glm::vec3(t), &scene_->scene().materials[std::size_t(t.w)]};
}

void IrradianceCacheTechnique::tabulateTriangles() {
  const scene::Scene& sc = scene_->scene();
  mesh_offsets_.clear();
  triangles_.clear();
  for (const scene::Mesh& mesh : sc.meshes) {
    mesh_offsets_.push_back(std::uint32_t(triangles_.size()));
    for (const glm::uvec3& t : mesh.triangles) {
      const glm::vec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
      const glm::vec3 normal = glm::cross(b - a, c - a);
      const float length = glm::length(normal);
      triangles_.emplace_back(length > 0 ? normal / length : glm::vec3(0.0f), float(mesh.material));
    }
  }
}

IrradianceCacheTechnique::IrradianceCacheTechnique(const ParameterValues& p)
    : placement_(recordPlacementSettings(p)),
      record_rays_(p.integer("record_rays")),
      light_samples_(p.integer("light_samples")),
      threads_(p.integer("threads")),
      reuse_records_(p.boolean("reuse_records")),
      // The hemisphere jitter of seed s is the stream the cache's seed s + 1 gave before seeds
      // had one default (0) across techniques, so the default run draws the rays it always drew.
      seed_(std::uint64_t(p.integer("seed")) + 1) {}

void IrradianceCacheTechnique::prepare(const GpuScene& scene, int width, int height) {
  scene_ = &scene;
  const auto start = Clock::now();
  caster_ = services_.ray_caster(scene.scene());
  caster_ms_ = millisecondsSince(start);
  tabulateTriangles();
  // The light samples of the GPU techniques (DirectLighting), lit here with shadow rays.
  const float extent = glm::length(scene.boundsMax() - scene.boundsMin());
  samples_.clear();
  directional_.clear();
  for (const LightSample& s : makeLightSamples(scene.scene(), scene.emitters(), light_samples_,
                                               light_samples_, 1e-3f * extent)) {
    samples_.push_back(toGpuLightSample(s));
    directional_.push_back(s.kind == LightSampleKind::kDirectional ? 1 : 0);
  }
  surfaces_.width = width;
  surfaces_.height = height;
  traceSurfaces();
  buildRecords();  // the first frame's cache; frames rebuild it only without reuse
}

glm::vec3 IrradianceCacheTechnique::unshadowedIrradiance(std::size_t s, const glm::vec3& p,
                                                         const glm::vec3& n,
                                                         scene::Ray& shadow) const {
  const gpu::GpuLightSample& sample = samples_[s];
  const bool directional = directional_[s] != 0;
  glm::vec3 wi, irradiance;
  if (directional) {
    wi = -glm::vec3(sample.axis);
    irradiance = glm::vec3(sample.intensity);
  } else {
    const glm::vec4 lit = gpu::pointSampleIrradiance(sample, p);
    if (lit.w == 0) return glm::vec3(0.0f);
    wi = glm::normalize(glm::vec3(sample.position) - p);
    irradiance = glm::vec3(lit);
  }
  const float cos_theta = glm::dot(n, wi);
  if (cos_theta <= 0) return glm::vec3(0.0f);
  const float eps = caster_->rayEpsilon();
  shadow.origin = p + eps * n;
  shadow.direction = wi;
  shadow.t_near = 0.0f;
  shadow.t_far = directional ? std::numeric_limits<float>::infinity()
                             : glm::length(glm::vec3(sample.position) - shadow.origin) - eps;
  return cos_theta * irradiance;
}

void IrradianceCacheTechnique::traceSurfaces() {
  const auto start = Clock::now();
  const scene::Scene& sc = scene_->scene();
  const int width = surfaces_.width, height = surfaces_.height;
  const std::size_t count = std::size_t(width) * std::size_t(height);
  surfaces_.position.assign(count, glm::vec3(0.0f));
  surfaces_.normal.assign(count, glm::vec3(0.0f));
  surfaces_.valid.assign(count, 0);
  albedo_.assign(count, glm::vec3(0.0f));
  own_light_.assign(count, glm::vec3(0.0f));
  const scene::CameraFrame camera = scene::makeCameraFrame(sc.camera, width, height);
  const glm::vec3 sky(sc.sky_radiance.r, sc.sky_radiance.g, sc.sky_radiance.b);
  parallelFor(std::size_t(height), threads_, 1, [&](std::size_t begin, std::size_t end) {
    std::vector<scene::Ray> rays;
    std::vector<glm::vec3> lit;
    std::vector<std::uint8_t> blocked;
    for (std::size_t y = begin; y < end; ++y)
      for (int x = 0; x < width; ++x) {
        const std::size_t i = surfaces_.index(x, int(y));
        // GL row y is image row height − 1 − y.
        const glm::vec3 d = scene::cameraRayDirection(camera, width, height, float(x) + 0.5f,
                                                      float(height) - float(y) - 0.5f);
        const scene::RayHit hit = caster_->intersect(camera.origin, d, 0.0f);
        if (!hit.valid()) {
          own_light_[i] = sky;
          continue;
        }
        const SurfaceHit surface = surfaceHit(hit);
        const scene::Material& m = *surface.material;
        const glm::vec3 wo = -d;
        const bool front = glm::dot(surface.normal, wo) > 0;
        const glm::vec3 n = front ? surface.normal : -surface.normal;
        const glm::vec3 p = camera.origin + hit.t * d;
        const glm::vec3 diffuse(m.diffuse.r, m.diffuse.g, m.diffuse.b);
        const glm::vec3 specular(m.specular.r, m.specular.g, m.specular.b);
        glm::vec3 light =
            front ? glm::vec3(m.emission.r, m.emission.g, m.emission.b) : glm::vec3(0.0f);
        // Every light sample's shadow ray of this pixel, traced as one batch.
        rays.clear();
        lit.clear();
        for (std::size_t k = 0; k < samples_.size(); ++k) {
          scene::Ray shadow;
          const glm::vec3 e = unshadowedIrradiance(k, p, n, shadow);
          if (e == glm::vec3(0.0f)) continue;
          rays.push_back(shadow);
          lit.push_back(gpu::evaluateBrdf(diffuse, specular, m.exponent,
                                          m.type == scene::MaterialType::kPhong, n, wo,
                                          shadow.direction) *
                        e);
        }
        blocked.resize(rays.size());
        caster_->occluded(rays, blocked);
        for (std::size_t k = 0; k < rays.size(); ++k)
          if (!blocked[k]) light += lit[k];
        surfaces_.position[i] = p;
        surfaces_.normal[i] = n;
        surfaces_.valid[i] = 1;
        albedo_[i] = diffuse;
        own_light_[i] = light;
      }
  });
  surfaces_ms_ = millisecondsSince(start);
}

gpu::IrradianceRecord IrradianceCacheTechnique::computeRecord(const glm::vec3& p,
                                                              const glm::vec3& n,
                                                              std::uint64_t stream) const {
  const WardStrata strata = wardStrata(record_rays_);
  const std::size_t count = std::size_t(strata.count());
  const glm::vec3 t = gpu::basisTangent(n), b = gpu::basisBitangent(n);
  const glm::vec3 origin = p + caster_->rayEpsilon() * n;
  RecordRandom random(splitMixFinalise(seed_ ^ splitMix64(stream)));
  // The strata's rays leave one point: one coherent batch (Embree's ray streams).
  thread_local std::vector<scene::Ray> rays, shadows;
  thread_local std::vector<scene::RayHit> hits;
  thread_local std::vector<float> u_light;
  thread_local std::vector<std::uint8_t> blocked;
  thread_local std::vector<std::size_t> shadowed_sample;
  thread_local std::vector<glm::vec3> shadowed_radiance;
  rays.resize(count);
  hits.resize(count);
  u_light.resize(count);
  for (int j = 0; j < strata.theta; ++j)
    for (int k = 0; k < strata.phi; ++k) {
      const std::size_t i = std::size_t(j) * std::size_t(strata.phi) + std::size_t(k);
      const glm::vec2 u(random.next(), random.next());
      u_light[i] = random.next();
      rays[i] = {origin, wardDirection(t, b, n, j, k, strata, u)};
    }
  caster_->intersect(rays, hits, true);

  // The once-reflected light at each hit: ρ/π times the direct irradiance there, from one light
  // sample picked at random and weighted by their count (the GPU's atlas sums all of them); the
  // sky a ray escapes to is direct light, not this bounce.
  std::vector<HemisphereSample> samples(count);
  shadows.clear();
  shadowed_sample.clear();
  shadowed_radiance.clear();
  for (std::size_t i = 0; i < count; ++i) {
    if (!hits[i].valid()) continue;
    samples[i].distance = hits[i].t;
    if (samples_.empty()) continue;
    const glm::vec3 w = rays[i].direction;
    const SurfaceHit surface = surfaceHit(hits[i]);
    const glm::vec3 hit_normal = glm::dot(surface.normal, w) > 0 ? -surface.normal : surface.normal;
    const std::size_t pick =
        std::min(samples_.size() - 1, std::size_t(u_light[i] * float(samples_.size())));
    scene::Ray shadow;
    const glm::vec3 e = unshadowedIrradiance(pick, origin + hits[i].t * w, hit_normal, shadow);
    if (e == glm::vec3(0.0f)) continue;
    const scene::Rgb& rho = surface.material->diffuse;
    shadows.push_back(shadow);
    shadowed_sample.push_back(i);
    shadowed_radiance.push_back(float(samples_.size()) * gpu::kInvPi *
                                glm::vec3(rho.r, rho.g, rho.b) * e);
  }
  blocked.resize(shadows.size());
  caster_->occluded(shadows, blocked);
  for (std::size_t k = 0; k < shadows.size(); ++k)
    if (!blocked[k]) samples[shadowed_sample[k]].radiance = shadowed_radiance[k];
  return wardRecord(p, n, strata, samples);
}

void IrradianceCacheTechnique::buildRecords() {
  const auto start = Clock::now();
  records_.clear();
  RecordPlacement placement(surfaces_, scene_->camera(), placement_);
  for (;;) {
    const std::vector<glm::ivec2> round = placement.nextRound();
    if (round.empty()) break;
    std::vector<gpu::IrradianceRecord> fresh(round.size());
    parallelFor(round.size(), threads_, 1, [&](std::size_t begin, std::size_t end) {
      for (std::size_t r = begin; r < end; ++r) {
        const std::size_t i = surfaces_.index(round[r].x, round[r].y);
        fresh[r] = computeRecord(surfaces_.position[i], surfaces_.normal[i], i);
      }
    });
    placement.add(fresh);
    records_.insert(records_.end(), fresh.begin(), fresh.end());
  }
  rounds_ = placement.rounds();
  // The store the lookups search: built with the cache, not at every frame that reuses it.
  octree_.emplace(scene_->boundsMin(), scene_->boundsMax(), placement_.accuracy);
  for (const gpu::IrradianceRecord& record : records_) octree_->insert(record);
  records_ms_ = millisecondsSince(start);
}

void IrradianceCacheTechnique::interpolate() {
  const auto start = Clock::now();
  irradiance_.assign(surfaces_.valid.size(), glm::vec3(0.0f));
  parallelFor(irradiance_.size(), threads_, 4096, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      if (!surfaces_.valid[i]) continue;
      const glm::vec4 sum = octree_->lookup(surfaces_.position[i], surfaces_.normal[i]);
      if (sum.w > 0) irradiance_[i] = glm::vec3(sum) / sum.w;
    }
  });
  interpolation_ms_ = millisecondsSince(start);
}

void IrradianceCacheTechnique::render(Frame& frame) {
  {
    auto pass = frame.profiler.pass(kSurfacesPass);
    traceSurfaces();
  }
  if (!reuse_records_) {
    auto pass = frame.profiler.pass(kRecordsPass);
    buildRecords();
  }
  {
    auto pass = frame.profiler.pass(kInterpolationPass);
    interpolate();
  }
  auto pass = frame.profiler.pass(kUploadPass);
  std::vector<glm::vec4> pixels(irradiance_.size());
  for (std::size_t i = 0; i < pixels.size(); ++i)
    pixels[i] = glm::vec4(own_light_[i] + gpu::kInvPi * albedo_[i] * irradiance_[i], 1.0f);
  glTextureSubImage2D(frame.target.color().id(), 0, 0, 0, surfaces_.width, surfaces_.height,
                      GL_RGBA, GL_FLOAT, pixels.data());
}

std::vector<AuxiliaryImage> IrradianceCacheTechnique::auxiliaryImages() {
  image::Image irradiance(surfaces_.width, surfaces_.height, 3);
  for (int y = 0; y < surfaces_.height; ++y)
    for (int x = 0; x < surfaces_.width; ++x) {
      const glm::vec3 e = irradiance_[surfaces_.index(x, y)];
      float* out = irradiance.pixel(x, surfaces_.height - 1 - y);
      for (int c = 0; c < 3; ++c) out[c] = e[c];
    }
  return {zonesAuxiliaryImage(surfaces_, scene_->camera(), records_, placement_.accuracy),
          {"irradiance", "the interpolated irradiance E (before ρ/π)", std::move(irradiance)}};
}

std::vector<TechniqueStatistic> IrradianceCacheTechnique::statistics() const {
  const double records = double(records_.size());
  return {{"records", records},
          {"record_rounds", double(rounds_)},
          {"rays_per_record", double(wardStrata(record_rays_).count())},
          {"records_ms", records_ms_},
          {"records_per_second", records_ms_ > 0 ? 1e3 * records / records_ms_ : 0.0},
          {"surfaces_ms", surfaces_ms_},
          {"threads", double(resolveThreadCount(threads_))},
          {"prepare_ray_caster_ms", caster_ms_}};
}

TechniqueInfo irradianceCacheTechniqueInfo() {
  TechniqueInfo info;
  info.name = "irradiance_cache";
  info.description =
      "CPU baseline: direct light plus one bounce (up to LDDE) from Ward's irradiance cache, "
      "Embree rays, an octree, every core";
  info.source = "SIGGRAPH 2008 course notes, Irradiance cache splatting (Ward's cache, §1)";
  info.parameters = joinParameterTables(
      {irradianceCacheParameters(),
       {
           numericParameter("record_rays", ParameterType::kInteger, "512", 4, 65536, "",
                            "hemisphere rays per record, stratified M × N with N ≈ πM (Ward & "
                            "Heckbert)"),
           lightSamplesParameter(),
           numericParameter(
               "threads", ParameterType::kInteger, "0", 0, 1024, "",
               "worker threads; 0: one per hardware thread (results do not depend on it)"),
           seedParameter("seed of the hemisphere rays' jitter"),
       }});
  info.passes.add(passPath({kFramePass, kSurfacesPass}),
                  "CPU: primary rays and their direct light (shadow rays to the light samples)");
  info.passes.add(
      passPath({kFramePass, kRecordsPass}),
      "CPU: the cache rebuilt (without reuse): traversal, stratified hemisphere rays, octree");
  info.passes.add(passPath({kFramePass, kInterpolationPass}),
                  "CPU: the octree looked up at every pixel");
  info.passes.add(passPath({kFramePass, kUploadPass}), "the image copied into the frame");
  info.auxiliary_images = {
      zonesImageDeclaration(),
      {"irradiance", "the interpolated irradiance E (before ρ/π)"},
  };
  info.statistics = irradianceCacheStatistics({
      {"rays_per_record", "hemisphere rays traced per record"},
      {"surfaces_ms", "time of the primary rays and their direct light"},
      {"threads", "worker threads used"},
      {"prepare_ray_caster_ms", "time to build the ray caster's BVH"},
  });
  info.needs = {TechniqueNeed::kRayCaster};
  info.create = [](const ParameterValues& values) -> std::unique_ptr<Technique> {
    return std::make_unique<IrradianceCacheTechnique>(values);
  };
  return info;
}

}  // namespace gib::rt
