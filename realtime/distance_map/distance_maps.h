// Distance maps (book §6.1, §6.3, §7.3): cube maps taken from a reference point o near an
// object, each texel holding the radiance of the surface it sees and that surface's distance
// from o, so that a ray from any point near o can be traced through the map (distance_map.glsl)
// and a texel can stand for an area light at a known place (§7.3). One map per object, all in
// one cube-map array; every map leaves out its own object (the environment of a specular object
// is everything else, §6.2), and rounds of composing let maps show each other's objects (§6.3).
#pragma once

#include "image/image.h"
#include "realtime/distance_map/distance_map_shared.h"
#include "realtime/gbuffer/gbuffer.h"
#include "realtime/gl/objects.h"
#include "realtime/gl/stream_buffer.h"
#include "realtime/lighting/direct_lighting.h"
#include "realtime/render_target.h"
#include "scene/scene.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

namespace gib::rt {

class GpuScene;

// An object with a map: a mesh, its triangles' range in the scene's list (GpuScene's order), its
// bounds and the map's reference point o.
struct DistanceMapObject {
  std::size_t mesh = 0;
  int first_triangle = 0, end_triangle = 0;
  glm::vec3 bounds_min{0.0f}, bounds_max{0.0f};
  glm::vec3 reference_point{0.0f};
};

// Mesh `mesh` of the scene as an object, o the centre of its bounds.
DistanceMapObject meshObject(const scene::Scene& scene, std::size_t mesh);
// Every mesh with triangles whose material is a mirror or glass (scene::isIdealSpecular), in
// order: the specular objects of §6.2-6.3.
std::vector<DistanceMapObject> specularObjects(const scene::Scene& scene);

// The camera's pixels that see one of the objects (GBuffer::albedo's triangle codes): one channel,
// 1 on an object, pixel (0,0) at the top left, what the techniques name as their measured region
// (Technique::measuredRegion).
image::Image objectPixels(const GBuffer& camera, const std::vector<DistanceMapObject>& objects);

// Where each map is taken from: the object's centre (the book's §6.2), or the centre of the
// scene's bounds for every map (the room's centre of Figs. 6.2 and 6.6).
enum class ReferencePoint { kObjectCentre, kSceneCentre };
void placeReferencePoints(std::vector<DistanceMapObject>& objects, ReferencePoint where,
                          const glm::vec3& scene_min, const glm::vec3& scene_max);

// How rays are traced through a map (gpu::kSearch…, kFresnel…), for the maps' own specular
// texels and the camera's.
struct DistanceMapSearch {
  int method = gpu::kSearchSecant;
  int linear_steps = 15;
  int secant_steps = 1;
  int fresnel = gpu::kFresnelSchlick;
};

class DistanceMaps {
 public:
  // Maps of `resolution`² texels per face for the objects (at most gpu::kMaxDistanceMapObjects);
  // allocates the views' G-buffer and light, and two arrays for the rounds.
  DistanceMaps(const GpuScene& scene, std::vector<DistanceMapObject> objects, int resolution);

  const std::vector<DistanceMapObject>& objects() const { return objects_; }
  int resolution() const { return resolution_; }
  void setSearch(const DistanceMapSearch& search) {
    search_ = search;
    writeBlock();
  }

  // Rasterises every map's six views (each without its own object) into the views' G-buffer.
  void rasterise(const GpuScene& scene);
  // Clears the views' light; then DirectLighting adds into them through litView.
  void clearLight() const;
  LitView litView(std::string_view pass) const {
    return {&*views_, &*light_, pass, /*normals_face_viewer=*/true};
  }
  // Composes the maps from the views and their light, `rounds` times (the first from black
  // maps): after it, maps() shows paths with up to rounds − 1 specular vertices past the surface
  // a map sees.
  void compose(const GpuScene& scene, int rounds);
  // The last round's maps: GL_TEXTURE_CUBE_MAP_ARRAY, RGBA32F, layer 6·object + face.
  const gl::Texture& maps() const { return maps_[current_]; }
  // Binds maps() and the objects' block for a pass that reads them (distance_map.glsl).
  void bind() const;
  // The maps averaged down to `size`² texels per face (§7.3), radiance and distance alike, into
  // `destination` (a cube-map array of that size and as many cubes); size divides resolution().
  void downsample(const gl::Texture& destination) const;

 private:
  // The objects' block, written when the objects or the search change, not per pass.
  void writeBlock();

  std::vector<DistanceMapObject> objects_;
  int resolution_;
  float near_, far_;
  DistanceMapSearch search_;
  std::optional<GBuffer> views_;
  std::optional<RenderTarget> light_;
  gl::Texture maps_[2];
  int current_ = 0;
  gl::Buffer block_;
  gl::Program compose_, downsample_;
};

}  // namespace gib::rt
