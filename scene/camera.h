// The one definition of a pixel's ray, shared by the reference and the GL renderers so that both
// produce the same pixel for the same ray.
#pragma once

#include "scene/scene.h"

namespace gib::scene {

struct CameraFrame {
  glm::vec3 origin;
  glm::vec3 forward;  // unit, towards look_at
  glm::vec3 right;    // unit, image +x
  glm::vec3 up;       // unit, image −y (pixel rows grow downwards)
  float tan_half_fov_y;
  float aspect;  // width / height
};

CameraFrame makeCameraFrame(const Camera& camera, int width, int height);

// Unit direction through the image point (x, y) in pixel units: (0,0) is the top-left corner of
// the image, (0.5,0.5) the centre of pixel (0,0), (width,height) the bottom-right corner.
glm::vec3 cameraRayDirection(const CameraFrame& frame, int width, int height, float x, float y);

}  // namespace gib::scene
