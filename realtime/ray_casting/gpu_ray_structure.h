// A ray-casting structure on the GPU (book Ch. 5): its data uploaded as buffer textures at the
// units of ray_casting_shared.h, and the GLSL function that casts one ray through it. Every
// structure's shader file defines one function of this signature, in the set's coordinates
// (ivm_triangles.h: the ray's origin moved by −IvmTriangleSet::origin):
//
//   RayCastHit castRay<Name>(vec3 o, vec3 d, float t_min, float t_max);
//
// and a pass that casts rays includes "realtime/ray_casting/cast_ray.glsl", which includes every
// structure's file and calls the one the define GIB_CAST_RAY names (castDefines()).
#pragma once

#include "realtime/gl/objects.h"
#include "realtime/ray_casting/ivm_triangles.h"

#include <cstddef>
#include <string>
#include <string_view>

namespace gib::rt {

class GpuRayStructure {
 public:
  virtual ~GpuRayStructure() = default;
  // Its name in tables and raycast.json (brute_force, loose_kd_tree, bvh).
  virtual std::string_view name() const = 0;
  // The GLSL function that casts a ray through it (castRayBvh, ...).
  virtual std::string_view castFunction() const = 0;
  // Binds its buffer textures to kRayTrianglesUnit and its other units.
  virtual void bind() const = 0;
  // The bytes of GPU memory its data take (what raycast.json reports).
  virtual std::size_t bytes() const = 0;

  // "#define GIB_CAST_RAY <castFunction>\n": the defines of a program that casts through it.
  std::string castDefines() const;
};

// The triangles of a set in a structure's order, as the buffer texture at kRayTrianglesUnit.
class GpuRayTriangles {
 public:
  GpuRayTriangles() = default;
  GpuRayTriangles(const IvmTriangleSet& set, std::span<const std::uint32_t> order);
  // In the set's own order (the brute force's and the ray engine's: slot = list index).
  explicit GpuRayTriangles(const IvmTriangleSet& set);
  void bind() const;
  std::size_t bytes() const { return buffer_.bytes(); }

 private:
  gl::Buffer buffer_;
  gl::Texture texture_;
};

// §5.1 on its own: every ray tested against every triangle in one loop (castRayBruteForce). The
// baseline the structures are measured against, and usable on small scenes only.
class GpuBruteForce final : public GpuRayStructure {
 public:
  explicit GpuBruteForce(const IvmTriangleSet& set);
  std::string_view name() const override { return "brute_force"; }
  std::string_view castFunction() const override { return "castRayBruteForce"; }
  void bind() const override { triangles_.bind(); }
  std::size_t bytes() const override { return triangles_.bytes(); }

 private:
  GpuRayTriangles triangles_;
};

// Throws std::runtime_error naming what is missing when the driver offers fewer texture units
// than kRayFlagsUnit + 1 or buffer textures smaller than `texels`.
void checkRayCastingLimits(std::size_t texels);

}  // namespace gib::rt
