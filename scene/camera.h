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
  // The thin lens (Camera::lens_radius, focusDistance): 0 for the pinhole.
  float lens_radius = 0.0f;
  float focus_distance = 0.0f;
};

CameraFrame makeCameraFrame(const Camera& camera, int width, int height);

// Unit direction through the image point (x, y) in pixel units: (0,0) is the top-left corner of
// the image, (0.5,0.5) the centre of pixel (0,0), (width,height) the bottom-right corner.
glm::vec3 cameraRayDirection(const CameraFrame& frame, int width, int height, float x, float y);

// Shirley and Chiu's concentric map of the unit square onto the unit disc: area-preserving, so a
// stratified square stays stratified on the disc.
glm::vec2 concentricDisc(glm::vec2 u);

// The camera ray through image point (x, y) for the lens sample `lens` in [0,1)²: from the lens
// point concentricDisc(lens) · lens_radius (in the right/up plane about the origin) towards the
// point where the pinhole ray through (x, y) meets the plane in focus, so that every lens point
// sees that plane's points at the same image point (the thin-lens equation's image of it). For the
// pinhole, lens is unused and the ray is {origin, cameraRayDirection(...)}, bit for bit.
struct CameraRay {
  glm::vec3 origin;
  glm::vec3 direction;  // unit
};
CameraRay cameraRay(const CameraFrame& frame, int width, int height, float x, float y,
                    glm::vec2 lens);

}  // namespace gib::scene
