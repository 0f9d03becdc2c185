#include "scene/camera.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace gib::scene {

CameraFrame makeCameraFrame(const Camera& camera, int width, int height) {
  CameraFrame f;
  f.origin = camera.position;
  f.forward = glm::normalize(camera.look_at - camera.position);
  // Right-handed: looking down `forward` with `up` up, `right` is forward × up.
  f.right = glm::normalize(glm::cross(f.forward, camera.up));
  f.up = glm::cross(f.right, f.forward);
  f.tan_half_fov_y = std::tan(glm::radians(camera.vertical_fov_deg) * 0.5f);
  f.aspect = float(width) / float(height);
  f.lens_radius = camera.lens_radius;
  f.focus_distance = focusDistance(camera);
  return f;
}

glm::vec3 cameraRayDirection(const CameraFrame& f, int width, int height, float x, float y) {
  float ndc_x = 2.0f * x / float(width) - 1.0f;
  float ndc_y = 1.0f - 2.0f * y / float(height);  // rows grow downwards
  glm::vec3 d = f.forward + (ndc_x * f.tan_half_fov_y * f.aspect) * f.right +
                (ndc_y * f.tan_half_fov_y) * f.up;
  return glm::normalize(d);
}

glm::vec2 concentricDisc(glm::vec2 u) {
  const glm::vec2 p = 2.0f * u - 1.0f;
  if (p.x == 0 && p.y == 0) return p;
  constexpr float kQuarterPi = 0.785398163397448310f;
  // The square's rings onto the disc's circles: the larger coordinate is the radius, the other
  // sweeps the angle across that coordinate's quarter of the disc.
  const bool x_major = std::abs(p.x) > std::abs(p.y);
  const float r = x_major ? p.x : p.y;
  const float theta =
      x_major ? kQuarterPi * (p.y / p.x) : 2.0f * kQuarterPi - kQuarterPi * (p.x / p.y);
  return r * glm::vec2(std::cos(theta), std::sin(theta));
}

CameraRay cameraRay(const CameraFrame& f, int width, int height, float x, float y, glm::vec2 lens) {
  const glm::vec3 pinhole = cameraRayDirection(f, width, height, x, y);
  if (f.lens_radius == 0) return {f.origin, pinhole};
  // The pinhole ray's point on the plane in focus, at focus_distance along forward.
  const glm::vec3 focus = f.origin + pinhole * (f.focus_distance / glm::dot(pinhole, f.forward));
  const glm::vec2 disc = f.lens_radius * concentricDisc(lens);
  const glm::vec3 origin = f.origin + disc.x * f.right + disc.y * f.up;
  return {origin, glm::normalize(focus - origin)};
}

}  // namespace gib::scene
