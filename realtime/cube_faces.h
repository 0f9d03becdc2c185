// The six 90° views of a cube map in OpenGL's face order (+x, −x, +y, −y, +z, −z), with the up
// vectors that make a face rendered with lookAt read back correctly through a direction lookup:
// texel (i, j) of face f, j counted from the bottom row as the framebuffer stores it, looks along
// sh::cubeTexelDirection(f, i, j, size). Shadow cube maps and the irradiance volume's probes
// both render through these.
#pragma once

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/mat4x4.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

namespace gib::rt {

inline constexpr glm::vec3 kCubeFaceAxis[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                               {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
inline constexpr glm::vec3 kCubeFaceUp[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1},
                                             {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};

// View-projection of face `face` seen from `eye`.
inline glm::mat4 cubeFaceViewProjection(const glm::vec3& eye, int face, float near_plane,
                                        float far_plane) {
  return glm::perspective(glm::radians(90.0f), 1.0f, near_plane, far_plane) *
         glm::lookAt(eye, eye + kCubeFaceAxis[face], kCubeFaceUp[face]);
}

}  // namespace gib::rt
