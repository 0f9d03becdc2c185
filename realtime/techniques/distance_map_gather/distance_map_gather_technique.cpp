#include "realtime/techniques/distance_map_gather/distance_map_gather_technique.h"

#include "common/input_error.h"
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/gpu_commands.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/pipeline_state.h"
#include "realtime/gl/shader_library.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/ray_casting/ivm_triangles.h"
#include "realtime/ray_casting/ray_structures.h"
#include "realtime/render_target.h"
#include "realtime/techniques/distance_map_gather/distance_map_gather_shared.h"
#include "scene/path_expression.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <memory>
#include <string>

namespace gib::rt {

namespace {

constexpr const char* kGatherShader = "realtime/techniques/distance_map_gather/gather.frag.glsl";

// "0 'floor', 1 'ceiling', …": the meshes a message offers.
std::string meshList(const scene::Scene& scene) {
  std::string list;
  for (std::size_t m = 0; m < scene.meshes.size(); ++m)
    list += fmt::format("{}{} '{}'", m ? ", " : "", m, scene.meshes[m].name);
  return list;
}

// A cube-map array of `size`² faces, `cubes` cubes, read at texel centres (nearest) or between
// them (the irradiance map, linear).
gl::Texture cubeArray(int size, int cubes, GLenum filter) {
  gl::Texture texture = gl::Texture::makeCubeArray(GL_RGBA32F, size, cubes);
  texture.setFilter(filter, filter);
  texture.setWrap(GL_CLAMP_TO_EDGE);
  return texture;
}

}  // namespace

DistanceMapGatherTechnique::DistanceMapGatherTechnique(const ParameterValues& p)
    : surface_lighting_(p),
      object_parameter_(p.integer("object")),
      resolution_(p.integer("map_resolution")),
      gather_size_(p.integer("gather_resolution")),
      mode_(p.text("mode") == "irradiance_map" ? gpu::kGatherFromIrradianceMap
                                               : gpu::kGatherFromDistanceMap),
      solid_angle_(p.text("solid_angle") == "polygon" ? gpu::kSolidAnglePolygon
                                                      : gpu::kSolidAngleDisc),
      peak_only_(p.boolean("glossy_peak_only")),
      visibility_(p.boolean("visibility")),
      reference_point_(p.text("reference_point") == "scene_centre"
                           ? ReferencePoint::kSceneCentre
                           : ReferencePoint::kObjectCentre) {}

scene::PathClass DistanceMapGatherTechnique::pathClass() const {
  return scene::PathClass::ofExpression(
      scene::PathExpression::parse(std::string(kDistanceMapGatherPathExpression)).text());
}

DistanceMapObject DistanceMapGatherTechnique::chooseObject(const scene::Scene& scene) const {
  const int count = int(scene.meshes.size());
  const int index = object_parameter_ < 0 ? count - 1 : object_parameter_;
  if (index < 0 || index >= count)
    throw InputError(fmt::format(
        "distance_map_gather parameter object = {}: scene '{}' has {} meshes ({}); set object to "
        "a mesh index from 0 to {}, or -1 for the last",
        object_parameter_, scene.name, count, meshList(scene), count - 1));
  const scene::Mesh& mesh = scene.meshes[std::size_t(index)];
  if (mesh.triangles.empty())
    throw InputError(fmt::format(
        "distance_map_gather parameter object = {}: mesh {} '{}' of scene '{}' has no triangles; "
        "choose a mesh with triangles: {}",
        object_parameter_, index, mesh.name, scene.name, meshList(scene)));
  if (scene.materials[mesh.material].isEmissive())
    throw InputError(fmt::format(
        "distance_map_gather parameter object = {}: mesh {} '{}' of scene '{}' emits light, which "
        "the gather would replace; choose a diffuse or glossy mesh: {}",
        object_parameter_, index, mesh.name, scene.name, meshList(scene)));
  return meshObject(scene, std::size_t(index));
}

void DistanceMapGatherTechnique::prepare(const GpuScene& scene, int width, int height) {
  scene_ = &scene;
  std::vector<DistanceMapObject> objects = {chooseObject(scene.scene())};
  placeReferencePoints(objects, reference_point_, scene.boundsMin(), scene.boundsMax());
  const scene::Mesh& mesh = scene.scene().meshes[objects[0].mesh];
  exponent_ = scene.scene().materials[mesh.material].exponent;
  surface_lighting_.prepare(scene, width, height);
  maps_.emplace(scene, std::move(objects), resolution_);
  if (mode_ == gpu::kGatherFromIrradianceMap) {
    low_res_ = cubeArray(gpu::kIrradianceSourceSize, 1, GL_NEAREST);
    irradiance_ = cubeArray(gpu::kIrradianceMapSize, 2, GL_LINEAR);
    irradiance_program_ = gl::buildProgram(
        {{GL_COMPUTE_SHADER, "realtime/techniques/distance_map_gather/irradiance.comp.glsl"}});
  } else {
    low_res_ = cubeArray(gather_size_, 1, GL_NEAREST);
    // The gather reads no irradiance map, but its sampler needs a complete texture.
    irradiance_ = cubeArray(1, 2, GL_NEAREST);
  }
  std::string defines;
  glm::vec3 set_origin(0.0f);
  if (visibility_) {
    // Every triangle: the object hides texels from itself (a torus's hole) as the walls do.
    const IvmTriangleSet set = buildIvmTriangles(scene.scene());
    structure_ = makeGpuRayStructure("bvh", set);
    set_origin = glm::vec3(set.origin);
    defines = structure_->castDefines() + "#define GATHER_VISIBILITY 1\n";
  }
  gather_ = gl::FullScreenPass(kGatherShader, defines);
  capture_ = gl::FullScreenPass(kGatherShader, defines + "#define CAPTURE_GATHER 1\n");
  if (visibility_) {
    const float diagonal = glm::length(scene.boundsMax() - scene.boundsMin());
    for (const gl::FullScreenPass* pass : {&gather_, &capture_}) {
      pass->program().set("u_set_origin", set_origin);
      pass->program().set("u_ray_offset", gpu::kGatherRayOffsetFraction * diagonal);
    }
  }
}

void DistanceMapGatherTechnique::render(Frame& frame) {
  drawSurfacesAndMaps(surface_lighting_, *scene_, *maps_, /*rounds=*/1, frame);
  {
    auto pass = frame.profiler.pass(kDownsamplePass);
    maps_->downsample(low_res_);
  }
  if (mode_ == gpu::kGatherFromIrradianceMap) {
    auto pass = frame.profiler.pass(kIrradianceConvolutionPass);
    convolveIrradiance();
  }
  auto pass = frame.profiler.pass(kFinalGatherPass);
  frame.target.bind();
  drawGather(gather_);
}

void DistanceMapGatherTechnique::convolveIrradiance() {
  irradiance_program_.use();
  irradiance_program_.set("u_exponent", exponent_);
  low_res_.bind(gpu::kLowResMapUnit);
  glBindImageTexture(gpu::kImageDestinationUnit, irradiance_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY,
                     GL_RGBA32F);
  const GLuint groups = GLuint(gpu::kIrradianceMapSize / gpu::kIrradianceGroupSize);
  gl::dispatchCompute(groups, groups, 12);  // two cubes of six faces
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void DistanceMapGatherTechnique::drawGather(const gl::FullScreenPass& pass) const {
  pass.use();
  const DistanceMapObject& object = maps_->objects()[0];
  const gl::Program& program = pass.program();
  program.set("u_object_triangles", glm::ivec2(object.first_triangle, object.end_triangle));
  program.set("u_reference_point", object.reference_point);
  program.set("u_size", gather_size_);
  program.set("u_mode", mode_);
  program.set("u_solid_angle", solid_angle_);
  program.set("u_peak_only", int(peak_only_));
  scene_->bindSceneBuffers();
  surface_lighting_.gbuffer().bindTextures();
  surface_lighting_.gbuffer().albedo().bind(gpu::kDistanceMapCodeUnit);
  low_res_.bind(gpu::kLowResMapUnit);
  irradiance_.bind(gpu::kIrradianceMapUnit);
  if (structure_) structure_->bind();
  // Replaces what SurfaceLighting wrote at the object's pixels; the caller's scope has no
  // blending.
  pass.draw();
}

std::vector<AuxiliaryImage> DistanceMapGatherTechnique::auxiliaryImages() {
  const int width = surface_lighting_.gbuffer().width();
  const int height = surface_lighting_.gbuffer().height();
  // The last frame's gather again, alone, with the texels each pixel gathered.
  std::vector<image::Image> captured =
      drawCaptured(width, height, 1, [&] { drawGather(capture_); });
  const image::Image& counts = captured[1];
  double sum = 0, pixels = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      if (counts.pixel(x, y)[3] > 0.0f) {
        sum += counts.pixel(x, y)[0];
        pixels += 1;
      }
  texels_mean_ = pixels > 0 ? sum / pixels : 0.0;
  object_pixels_ = pixels;
  measured_ = true;

  std::vector<AuxiliaryImage> images;
  images.push_back(
      {"gather", "the light the object gathers (its pixels only)", std::move(captured[0])});
  images.push_back({"low_res_map",
                    "the downsampled map the gather reads (M² per face; 16² with "
                    "mode=irradiance_map), faces +x −x +y −y +z −z",
                    unfoldCubes(low_res_)});
  return images;
}

std::optional<image::Image> DistanceMapGatherTechnique::measuredRegion() {
  return objectPixels(surface_lighting_.gbuffer(), maps_->objects());  // the gathering object
}

std::vector<TechniqueStatistic> DistanceMapGatherTechnique::statistics() const {
  const double texels = 6.0 * gather_size_ * gather_size_;
  return {{"map_texels", 6.0 * resolution_ * resolution_},
          {"low_res_texels", mode_ == gpu::kGatherFromIrradianceMap ? 0.0 : texels}};
}

std::vector<TechniqueStatistic> DistanceMapGatherTechnique::finalStatistics() const {
  if (!measured_) return {};
  return {{"texels_gathered_mean", texels_mean_}, {"object_pixels", object_pixels_}};
}

TechniqueInfo distanceMapGatherTechniqueInfo() {
  TechniqueInfo info;
  info.name = "distance_map_gather";
  info.description =
      "one diffuse or glossy object shaded by final gathering from a distance map downsampled "
      "to area lights (or by a classic irradiance map), over the shared direct light";
  info.source =
      "Szirmay-Kalos et al., GPU-Based Techniques for Global Illumination Effects, §7.3 and "
      "Figs. 7.10-7.13 (and §4.2.2 for the irradiance map)";
  info.parameters = joinParameterTables(
      {{numericParameter("object", ParameterType::kInteger, "-1", -1, 1000000, "",
                         "the mesh shaded by the gather, by its index in the scene; -1: the last "
                         "mesh (the room's object, the Cornell box's tall block)"),
        integerChoiceParameter("map_resolution", 256, {16, 32, 64, 128, 256, 512}, "",
                               "texels per edge of each face of the distance map (the book's "
                               "6 × 256²)"),
        integerChoiceParameter("gather_resolution", 4, {1, 2, 4, 8}, "",
                               "M: texels per edge of each face of the downsampled map, each an "
                               "area light (the book's 4 and 2)"),
        choiceParameter("mode", "distance_map", {"distance_map", "irradiance_map"},
                        "final gathering from the distance map (§7.3), or the classic irradiance "
                        "environment map of §4.2.2 from the same map, positions ignored"),
        choiceParameter("solid_angle", "disc", {"disc", "polygon"},
                        "a texel's solid angle: eq. 7.7 (a disc) or eq. 7.6 (a small planar "
                        "polygon, A cos θ/d²)"),
        booleanParameter("glossy_peak_only", false,
                         "a Phong object gathers only the texels where its lobe is at least 10% "
                         "of its peak (the book's Fig. 7.10, lower row)"),
        booleanParameter("visibility", false,
                         "cast a shadow ray through a GPU BVH from the shaded point to each "
                         "texel's surface (the book tests none: this measures what that costs)"),
        choiceParameter("reference_point", "object_centre", {"object_centre", "scene_centre"},
                        "where the map is taken from: the object's centre, or the centre of the "
                        "scene")},
       SurfaceLighting::parameters()});
  declareDistanceMapPasses(info.passes, {"the six views of the object's map, without the object",
                                         "the map composed from its views' emission and light"});
  info.passes.add(passPath({kFramePass, kDownsamplePass}),
                  "the map averaged to M² texels per face (16² with mode=irradiance_map)");
  info.passes.add(passPath({kFramePass, kIrradianceConvolutionPass}),
                  "mode=irradiance_map: the diffuse and glossy irradiance maps convolved");
  info.passes.add(passPath({kFramePass, kFinalGatherPass}),
                  "the object's pixels: every low-resolution texel gathered (or the irradiance "
                  "maps looked up)");
  info.auxiliary_images = {
      {"gather", "the light the object gathers, its pixels only"},
      {"low_res_map", "the downsampled map the gather reads, faces +x −x +y −y +z −z"}};
  info.statistics = {
      {"map_texels", "texels of the distance map"},
      {"low_res_texels", "texels of the downsampled map, 6·M² (0 with mode=irradiance_map)"},
      {"texels_gathered_mean", "texels an object pixel gathers, on average over its pixels"},
      {"object_pixels", "pixels of the object in the image"}};
  info.needs = {TechniqueNeed::kShadedObject};
  info.create = [](const ParameterValues& values) -> std::unique_ptr<Technique> {
    return std::make_unique<DistanceMapGatherTechnique>(values);
  };
  return info;
}

}  // namespace gib::rt
