#include "realtime/techniques/hemispherical_gather/hemispherical_gather_technique.h"

#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/pipeline_state.h"
#include "realtime/gl/shader_library.h"
#include "realtime/technique_parameters.h"
#include "realtime/techniques/hemispherical_gather/hemispherical_gather_shared.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace gib::rt {

namespace {

constexpr std::string_view kInterpolatePass = "interpolation";

int projectionOf(const ParameterValues& p) {
  const std::string& name = p.text("projection");
  if (name == "perspective") return gpu::kProjectionPerspective;
  return name == "voxel_slices" ? gpu::kProjectionVoxelSlices : gpu::kProjectionHemispherical;
}

// The paper's sizes (§6.2): 256² for the 160° perspective view (45² pixels in its central 90°),
// 64² for the hemispherical one, 40² for the voxel slices' ("visually satisfying").
int viewSizeOf(const ParameterValues& p) {
  const int size = p.integer("view_size");
  if (size > 0) return size;
  switch (projectionOf(p)) {
    case gpu::kProjectionPerspective:
      return 256;
    case gpu::kProjectionVoxelSlices:
      return 40;
    default:
      return 64;
  }
}

}  // namespace

HemisphericalGatherTechnique::HemisphericalGatherTechnique(const ParameterValues& p)
    : projection_(projectionOf(p)),
      view_size_(viewSizeOf(p)),
      spacing_(p.integer("gather_spacing")),
      atlas_resolution_(p.integer("atlas")),
      tessellation_(p.integer("tessellation")),
      light_samples_(p.integer("light_samples")),
      slices_(p.integer("slices")),
      slice_size_(p.integer("slice_size")),
      surface_lighting_(p) {}

void HemisphericalGatherTechnique::prepare(const GpuScene& scene, int width, int height) {
  scene_ = &scene;
  surface_lighting_.prepare(scene, width, height);
  const float extent = std::max(glm::length(scene.boundsMax() - scene.boundsMin()), 1e-6f);

  // The directly lit scene as a radiance atlas, from the same light samples as the camera's.
  atlas_ = atlas::makeDirectRadianceAtlas(scene, atlas_resolution_, light_samples_);
  mesh_.emplace(atlas_.triangles, atlas_.layout, tessellation_);

  // The slices need no tessellation (orthographic views keep edges straight): built from the
  // scene's own triangles, 4^levels fewer than the views draw.
  if (projection_ == gpu::kProjectionVoxelSlices)
    voxels_.emplace(scene, atlas::AtlasMesh(atlas_.triangles, atlas_.layout, 0), atlas_.radiance,
                    slices_, slice_size_);
  gather_.emplace(projection_, view_size_, spacing_, width, height, extent);
  interpolate_ =
      gl::FullScreenPass("realtime/techniques/hemispherical_gather/gather_interpolate.frag.glsl");
  const gl::Program& interpolate = interpolate_.program();
  gather_->setPointUniforms(interpolate);
  interpolate.set("u_plane_tolerance", 0.01f * extent);
}

void HemisphericalGatherTechnique::render(Frame& frame) {
  const GpuScene& scene = *scene_;
  surface_lighting_.render(scene, frame.target, frame.profiler);
  gather_->gather(scene, *mesh_, atlas_.radiance, surface_lighting_.gbuffer(), frame.profiler,
                  glm::vec3(0.0f), voxels_ ? &*voxels_ : nullptr);

  auto pass = frame.profiler.pass(kInterpolatePass);
  scene.bindSceneBuffers();
  surface_lighting_.gbuffer().bindTextures();
  gather_->irradiance().bind(gpu::kGatherIrradianceUnit);
  surface_lighting_.gbuffer().albedo().bind(gpu::kGBufferAlbedoUnit);
  frame.target.bind();
  const gl::PipelineScope adding({.blend = gl::kAdditiveBlend});
  interpolate_.draw();
}

std::vector<AuxiliaryImage> HemisphericalGatherTechnique::auxiliaryImages() {
  return {{"gather-irradiance",
           "irradiance at the gather points (one pixel per point, the grid over the image)",
           gl::readTexture(gather_->irradiance(), 3)},
          {"radiance-atlas", "the directly lit scene the gather views see (ρ/π · direct E)",
           gl::readTexture(atlas_.radiance, 3)}};
}

std::vector<TechniqueStatistic> HemisphericalGatherTechnique::statistics() const {
  const glm::ivec2 grid = gather_ ? gather_->grid() : glm::ivec2(0);
  return {{"gather_points", double(grid.x * grid.y)},
          {"view_size", double(view_size_)},
          {"points_per_batch", double(gather_ ? gather_->pointsPerBatch() : 0)},
          {"view_triangles", double(mesh_ ? mesh_->vertexCount() / 3 : 0)},
          {"prepare_atlas_ms", atlas_.milliseconds},
          {"prepare_voxels_ms", voxels_ ? voxels_->buildMilliseconds() : 0.0},
          {"voxel_slices_mb", voxels_ ? double(voxels_->bytes()) / 1e6 : 0.0}};
}

TechniqueInfo hemisphericalGatherTechniqueInfo() {
  TechniqueInfo info;
  info.name = "hemispherical_gather";
  info.description =
      "direct light plus one bounce (up to LDDE) gathered by rendering the directly lit scene "
      "around sparse points: 160° perspective or fish-eye (hemispherical) views";
  info.source =
      "Fournier & Péroche, Speeding up global illumination computations using programmable "
      "GPUs, §5";
  info.parameters = joinParameterTables(
      {{
           choiceParameter("projection", "hemispherical",
                           {"perspective", "hemispherical", "voxel_slices"},
                           "gather view: a 160° pinhole along the normal, the fish-eye projection "
                           "whose pixels all weigh the same, or the fish-eye of voxel slices with "
                           "the objects near the point drawn"),
           numericParameter(
               "view_size", ParameterType::kInteger, "0", 0, 1024, "pixels",
               "gather view side; 0: the paper's, 256 perspective, 64 hemispherical, 40 "
               "voxel slices"),
           numericParameter("slices", ParameterType::kInteger, "64", 2, 512, "",
                            "voxel slices: slabs per axis (the paper's 64)"),
           numericParameter("slice_size", ParameterType::kInteger, "64", 4, 1024, "texels",
                            "voxel slices: each face's side (the paper's 64)"),
           numericParameter("gather_spacing", ParameterType::kInteger, "8", 1, 64, "pixels",
                            "one gather point per spacing × spacing block of the image"),
           atlasParameter(256,
                          "radiance atlas texels per side (the directly lit scene the views see)"),
           numericParameter(
               "tessellation", ParameterType::kInteger, "3", 0, 4, "levels",
               "each triangle split into 4^levels for the views (the fish-eye bends edges)"),
       },
       SurfaceLighting::parameters()});
  SurfaceLighting::declarePasses(info.passes);
  const std::string gather = passPath({kFramePass, kGatherPass});
  info.passes.add(gather, "per batch of gather points: their views, then their sums");
  info.passes.add(passPath({gather, kGatherViewsPass}),
                  "the directly lit scene drawn around each gather point, a layer each");
  info.passes.add(passPath({gather, kGatherSlicesPass}),
                  "voxel slices: each view's pixels traced through the slices beyond the near box");
  info.passes.add(passPath({gather, kGatherSumPass}),
                  "each view summed into irradiance (cos θ dω per pixel)");
  info.passes.add(passPath({kFramePass, kInterpolatePass}),
                  "irradiance interpolated to every pixel, times ρ/π, added to the frame");
  info.auxiliary_images = {
      {"gather-irradiance",
       "irradiance at the gather points (one pixel per point, the grid over the image)"},
      {"radiance-atlas", "the directly lit scene the gather views see (ρ/π · direct E)"},
  };
  info.statistics = {
      {"gather_points", "gather points over the image"},
      {"view_size", "side of each gather view in pixels"},
      {"points_per_batch", "gather points whose views are drawn at once"},
      {"view_triangles", "triangles each gather view draws (after tessellation)"},
      {"prepare_atlas_ms", "time to build the directly lit radiance atlas"},
      {"prepare_voxels_ms", "time to build the voxel slices (voxel_slices only)"},
      {"voxel_slices_mb", "memory of the voxel slices (voxel_slices only)"},
  };
  info.create = [](const ParameterValues& values) -> std::unique_ptr<Technique> {
    return std::make_unique<HemisphericalGatherTechnique>(values);
  };
  return info;
}

}  // namespace gib::rt
