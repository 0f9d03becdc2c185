// The ray engine (book §5.2, Carr, Hall & Hart 2002): rays in two textures the size of the render
// target, one pixel per ray; every triangle drawn over the rays' pixels, its fragment shader
// intersecting the pixel's ray with it (§5.1) and writing the hit distance as depth, so that the
// depth test keeps the nearest. The hierarchical form of §5.3 splits the rays into tiles, encloses
// each tile's rays in a cone (a compute pass, as the book has it when the GPU makes the rays), and
// draws each triangle as one point per tile, which the vertex shader throws out when the
// triangle's bounding sphere misses the tile's cone.
//
// Ties in depth go to the triangle drawn first (GL's order of primitives within a draw): the
// lower list index. Depth is t/(t + s), s the scene's diagonal: monotonic in t on [0, ∞), so
// the depth test orders hits as t does, to float's precision.
#pragma once

#include "realtime/gl/objects.h"
#include "realtime/ray_casting/gpu_ray_structure.h"
#include "realtime/ray_casting/ray_cast_pass.h"
#include "realtime/render_target.h"

#include <memory>
#include <optional>
#include <string_view>
#include <vector>

namespace gib::rt {

class RayEngine {
 public:
  // `cones`: §5.3's tiles and cones; else §5.2's full-target pass per triangle. `tile_size`: the
  // tile's side in pixels (rays), at most the driver's largest point size.
  RayEngine(const IvmTriangleSet& set, bool cones, int tile_size = 16);

  std::string_view name() const { return cones_ ? "ray_engine_cones" : "ray_engine"; }
  // Lays the rays out row by row, `width` to a row (an image's width keeps neighbours together,
  // which the cones need), and makes the target.
  void setRays(const std::vector<CastRay>& rays, int width);
  // The cone pass (with cones) and the draw; returns at once.
  void cast();
  std::vector<gpu::RayCastHit> hits() const;
  // GPU memory: the triangles, spheres, rays, cones and the target.
  std::size_t bytes() const;
  std::size_t rayCount() const { return count_; }
  // With cones, after a cast: the fraction of (tile, triangle) pairs the cones let through (the
  // same test as the vertex shader's, on the read-back cones); 1 without cones.
  double keptPairFraction() const;
  // The cone records of the last cast (2 per tile, ray_engine_shared.h), read back.
  std::vector<glm::vec4> readCones() const;

 private:
  bool cones_;
  int tile_size_;
  float depth_scale_;
  std::size_t triangle_count_;
  GpuRayTriangles triangles_;
  std::vector<glm::vec4> spheres_cpu_;
  gl::Buffer spheres_buffer_;
  gl::Texture spheres_;
  gl::Program draw_program_, cone_program_;
  gl::VertexArray empty_vertices_;
  std::size_t count_ = 0;
  int width_ = 0, height_ = 0;                // the rays' layout: width_ to a row
  int target_width_ = 0, target_height_ = 0;  // the target: whole tiles with cones
  int tiles_x_ = 0, tiles_y_ = 0;
  gl::Texture origins_, directions_;
  gl::Buffer cones_buffer_;
  gl::Texture cones_texture_;
  std::unique_ptr<RenderTarget> target_;
};

}  // namespace gib::rt
