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
  return f;
}

glm::vec3 cameraRayDirection(const CameraFrame& f, int width, int height, float x, float y) {
  float ndc_x = 2.0f * x / float(width) - 1.0f;
  float ndc_y = 1.0f - 2.0f * y / float(height);  // rows grow downwards
  glm::vec3 d = f.forward + (ndc_x * f.tan_half_fov_y * f.aspect) * f.right +
                (ndc_y * f.tan_half_fov_y) * f.up;
  return glm::normalize(d);
}

}  // namespace gib::scene
