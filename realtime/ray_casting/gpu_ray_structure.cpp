#include "realtime/ray_casting/gpu_ray_structure.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <numeric>
#include <stdexcept>

namespace gib::rt {

std::string GpuRayStructure::castDefines() const {
  std::string upper(name());
  std::transform(upper.begin(), upper.end(), upper.begin(),
                 [](unsigned char c) { return char(std::toupper(c)); });
  return fmt::format("#define GIB_CAST_RAY {}\n#define GIB_RAY_STRUCTURE_{} 1\n", castFunction(),
                     upper);
}

GpuRayTriangles::GpuRayTriangles(const IvmTriangleSet& set, std::span<const std::uint32_t> order) {
  const std::vector<glm::vec4> texels = packRayTriangles(set, order);
  checkRayCastingLimits(texels.size());
  buffer_ = gl::Buffer::fromVector(texels, 0);
  texture_ = gl::Texture::makeBuffer(GL_RGBA32F, buffer_);
}

void GpuRayTriangles::bind() const {
  texture_.bind(GLuint(gpu::kRayTrianglesUnit));
}

GpuRayTriangles::GpuRayTriangles(const IvmTriangleSet& set)
    : GpuRayTriangles(set, [&] {
        std::vector<std::uint32_t> order(set.size());
        std::iota(order.begin(), order.end(), 0u);
        return order;
      }()) {}

GpuBruteForce::GpuBruteForce(const IvmTriangleSet& set) : triangles_(set) {}

void checkRayCastingLimits(std::size_t texels) {
  GLint units = 0, buffer_texels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &units);
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &buffer_texels);
  if (units <= gpu::kRayFlagsUnit)
    throw std::runtime_error(fmt::format(
        "the GL driver offers {} texture units per stage; GPU ray casting reads units up to {} "
        "(realtime/ray_casting/ray_casting_shared.h); use a driver that offers more",
        units, gpu::kRayFlagsUnit));
  if (texels > std::size_t(buffer_texels))
    throw std::runtime_error(fmt::format(
        "the scene needs a buffer texture of {} texels for GPU ray casting, and the GL driver "
        "offers {}; cast rays on a smaller scene",
        texels, buffer_texels));
}

}  // namespace gib::rt
