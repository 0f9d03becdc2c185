#include "realtime/techniques/distance_map_specular/distance_map_specular_technique.h"

#include "common/input_error.h"
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/pipeline_state.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/render_target.h"
#include "scene/path_expression.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <memory>

namespace gib::rt {

namespace {

constexpr const char* kSpecularShader =
    "realtime/techniques/distance_map_specular/specular.frag.glsl";

int searchMethod(const std::string& name) {
  if (name == "environment") return gpu::kSearchEnvironment;
  if (name == "parallax") return gpu::kSearchParallax;
  if (name == "linear") return gpu::kSearchLinear;
  return gpu::kSearchSecant;
}

}  // namespace

std::string distanceMapSpecularPathExpression(int rounds) {
  // A round is one object's interaction: a mirror's one specular vertex, or a glass's two (the
  // single refraction of §6.2 stands for the ray's way in and out, which the reference traces as
  // two vertices; the class of k = 1 would leave the glass black).
  return fmt::format("LD?S{{0,{}}}E", 2 * rounds);
}

DistanceMapSpecularTechnique::DistanceMapSpecularTechnique(const ParameterValues& p)
    : surface_lighting_(p),
      resolution_(p.integer("map_resolution")),
      rounds_(p.integer("rounds")),
      reference_point_(p.text("reference_point") == "scene_centre"
                           ? ReferencePoint::kSceneCentre
                           : ReferencePoint::kObjectCentre) {
  search_.method = searchMethod(p.text("search"));
  search_.linear_steps = p.integer("linear_steps");
  search_.secant_steps = p.integer("secant_steps");
  search_.fresnel = p.text("fresnel") == "exact" ? gpu::kFresnelExact : gpu::kFresnelSchlick;
}

scene::PathClass DistanceMapSpecularTechnique::pathClass() const {
  return scene::PathClass::ofExpression(
      scene::PathExpression::parse(distanceMapSpecularPathExpression(rounds_)).text());
}

void DistanceMapSpecularTechnique::prepare(const GpuScene& scene, int width, int height) {
  scene_ = &scene;
  std::vector<DistanceMapObject> objects = specularObjects(scene.scene());
  if (objects.size() > std::size_t(gpu::kMaxDistanceMapObjects))
    throw InputError(fmt::format(
        "scene '{}' has {} mirror and glass meshes; distance_map_specular keeps a map for at "
        "most {}: merge objects into fewer meshes",
        scene.scene().name, objects.size(), gpu::kMaxDistanceMapObjects));
  placeReferencePoints(objects, reference_point_, scene.boundsMin(), scene.boundsMax());
  surface_lighting_.prepare(scene, width, height);
  maps_.emplace(scene, std::move(objects), resolution_);
  maps_->setSearch(search_);
  specular_ = gl::FullScreenPass(kSpecularShader);
  capture_ = gl::FullScreenPass(kSpecularShader, "#define CAPTURE_SEARCH 1\n");
}

void DistanceMapSpecularTechnique::render(Frame& frame) {
  drawSurfacesAndMaps(surface_lighting_, *scene_, *maps_, rounds_, frame);
  auto pass = frame.profiler.pass(kSpecularPass);
  frame.target.bind();
  drawSpecular(specular_);
}

void DistanceMapSpecularTechnique::drawSpecular(const gl::FullScreenPass& pass) const {
  pass.use();
  scene_->bindSceneBuffers();
  surface_lighting_.gbuffer().bindTextures();
  surface_lighting_.gbuffer().albedo().bind(gpu::kDistanceMapCodeUnit);
  maps_->bind();
  // Replaces what SurfaceLighting wrote at a specular pixel (a black diffuse surface's light);
  // the caller's scope has no blending.
  pass.draw();
}

image::Image DistanceMapSpecularTechnique::searchError() {
  const int width = surface_lighting_.gbuffer().width();
  const int height = surface_lighting_.gbuffer().height();
  // The last frame's maps, searched again with the hit and ray written out.
  const std::vector<image::Image> captured =
      drawCaptured(width, height, 2, [&] { drawSpecular(capture_); });
  const image::Image& hit = captured[1];
  const image::Image& ray = captured[2];
  const image::Image origin = gl::readTexture(surface_lighting_.gbuffer().position(), 4);

  // The true first hit of each traced ray among what its map holds: everything but its object.
  const scene::Scene& scene = scene_->scene();
  const std::unique_ptr<scene::RayCaster> caster = services_.ray_caster(scene);
  const float epsilon = caster->rayEpsilon();
  const float diagonal = glm::length(scene_->boundsMax() - scene_->boundsMin());
  image::Image error(width, height, 3);
  double sum = 0, max_error = 0;
  std::size_t count = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      if (hit.pixel(x, y)[3] == 0.0f) continue;
      const glm::vec3 p(origin.pixel(x, y)[0], origin.pixel(x, y)[1], origin.pixel(x, y)[2]);
      const glm::vec3 d(ray.pixel(x, y)[0], ray.pixel(x, y)[1], ray.pixel(x, y)[2]);
      const std::size_t own_mesh = maps_->objects()[std::size_t(ray.pixel(x, y)[3])].mesh;
      float t_near = epsilon;
      scene::RayHit truth = caster->intersect(p, d, t_near);
      while (truth.valid() && truth.mesh == own_mesh)
        truth = caster->intersect(p, d, truth.t + epsilon);
      // A ray that leaves the scene has no hit to miss: the search ends in its direction too.
      if (!truth.valid()) continue;
      const glm::vec3 found(hit.pixel(x, y)[0], hit.pixel(x, y)[1], hit.pixel(x, y)[2]);
      // A search that ends on a texel of the sky (kDistanceMapNoSurface away: what o sees
      // through an opening) where Embree hits a surface is off by the scene's diagonal at most
      // in any sense that matters; computed unclamped, its square overflows float to inf.
      const float e = float(
          std::min(glm::length(glm::dvec3(found) - glm::dvec3(p + truth.t * d)), double(diagonal)));
      for (int c = 0; c < 3; ++c) error.pixel(x, y)[c] = e;
      sum += e;
      max_error = std::max(max_error, double(e));
      ++count;
    }
  search_error_mean_ = count ? sum / double(count) : 0.0;
  search_error_max_ = max_error;
  search_error_measured_ = true;
  return error;
}

std::vector<AuxiliaryImage> DistanceMapSpecularTechnique::auxiliaryImages() {
  std::vector<AuxiliaryImage> images;
  images.push_back({"search_error",
                    "the search's geometric error (scene units): from the hit it found to the "
                    "first hit on the same ray (Embree), 0 off the mirrors and glass",
                    searchError()});
  images.push_back({"maps",
                    "the distance maps' radiance, one object per row, faces +x −x +y −y "
                    "+z −z",
                    unfoldCubes(maps_->maps())});
  return images;
}

std::optional<image::Image> DistanceMapSpecularTechnique::measuredRegion() {
  return objectPixels(surface_lighting_.gbuffer(), maps_->objects());  // the mirrors and glass
}

std::vector<TechniqueStatistic> DistanceMapSpecularTechnique::statistics() const {
  return {{"map_objects", maps_ ? double(maps_->objects().size()) : 0.0},
          {"map_texels", maps_ ? 6.0 * resolution_ * resolution_ * maps_->objects().size() : 0.0}};
}

std::vector<TechniqueStatistic> DistanceMapSpecularTechnique::finalStatistics() const {
  if (!search_error_measured_) return {};
  return {{"search_error_mean", search_error_mean_}, {"search_error_max", search_error_max_}};
}

TechniqueInfo distanceMapSpecularTechniqueInfo() {
  TechniqueInfo info;
  info.name = "distance_map_specular";
  info.description =
      "mirror and glass objects reflecting and refracting their environment through distance "
      "maps searched along each ray, over the shared direct light";
  info.source =
      "Szirmay-Kalos et al., GPU-Based Techniques for Global Illumination Effects, §6.1-6.3 and "
      "Figs. 6.2, 6.6, 6.9, 6.11";
  info.parameters = joinParameterTables(
      {{integerChoiceParameter("map_resolution", 256, {16, 32, 64, 128, 256, 512}, "",
                               "texels per edge of each face of a distance map (the book's "
                               "6 × 256²)"),
        choiceParameter("search", "secant", {"environment", "parallax", "linear", "secant"},
                        "how a ray's hit is found in the map: classic environment mapping, "
                        "parallax correction (eq. 6.1), linear search, linear then secant search"),
        numericParameter("linear_steps", ParameterType::kInteger, "15", 1, 1024, "",
                         "samples of the linear search along the ray (the book's 15 and 80)"),
        numericParameter("secant_steps", ParameterType::kInteger, "1", 1, 64, "",
                         "secant steps after the linear search (the book's 1 and 10)"),
        choiceParameter("fresnel", "schlick", {"schlick", "exact"},
                        "Fresnel's function: eq. 1.6's approximation as the book, or the exact one "
                        "the reference uses"),
        numericParameter(
            "rounds", ParameterType::kInteger, "1", 1, 8, "",
            "rounds of map generation (§6.3): each adds one reflection of the other "
            "specular objects (the class is L D? S{0,2·rounds} E: a glass is two vertices)"),
        choiceParameter("reference_point", "object_centre", {"object_centre", "scene_centre"},
                        "where each map is taken from: its object's centre, or the centre of the "
                        "scene (the book's Figs. 6.2 and 6.6)")},
       SurfaceLighting::parameters()});
  declareDistanceMapPasses(
      info.passes, {"the six views of every specular object's map, without the object",
                    "the maps composed from their views' emission and light, `rounds` times"});
  info.passes.add(passPath({kFramePass, kSpecularPass}),
                  "the mirror and glass pixels' rays searched in their objects' maps");
  info.auxiliary_images = {
      {"search_error",
       "per mirror or glass pixel, the distance (scene units) from the hit the "
       "search found to the true first hit on the same ray"},
      {"maps", "the distance maps' radiance, one object per row"}};
  info.statistics = {{"map_objects", "specular objects, one distance map each"},
                     {"map_texels", "texels of all the distance maps"},
                     {"search_error_mean",
                      "mean geometric error of the search over the mirror and glass pixels "
                      "(scene units)"},
                     {"search_error_max", "largest geometric error of the search (scene units)"}};
  info.needs = {TechniqueNeed::kSpecularMaterials, TechniqueNeed::kRayCaster};
  info.create = [](const ParameterValues& values) -> std::unique_ptr<Technique> {
    return std::make_unique<DistanceMapSpecularTechnique>(values);
  };
  return info;
}

}  // namespace gib::rt
