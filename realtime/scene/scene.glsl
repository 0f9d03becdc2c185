// The scene as GpuScene (realtime/gpu_scene.h) uploads it: materials in a storage buffer and the
// camera in a uniform block. Bindings and layouts must stay equal to the C++ side
// (tests/realtime/gpu_scene_test.cpp checks them). Vertex attributes: scene/vertex.glsl.

#define kMaterialBinding 0  // = gib::rt::kMaterialBinding
#define kCameraBinding 0    // = gib::rt::kCameraBinding

#define kMaterialLambert 0
#define kMaterialPhong 1

struct Material {
  vec4 diffuse_type;       // rgb diffuse reflectance, w: kMaterialLambert or kMaterialPhong
  vec4 specular_exponent;  // rgb specular reflectance, w: Phong exponent n
  vec4 emission;           // rgb radiance emitted from the front side, w unused
};

layout(std430, binding = kMaterialBinding) readonly buffer Materials {
  Material materials[];
};

// The pinhole camera of scene::cameraRayDirection (see gib::rt::cameraTransform).
layout(std140, binding = kCameraBinding) uniform Camera {
  mat4 view_projection;
  mat4 view;
  mat4 projection;
  vec4 position;    // xyz: eye, w 1
  vec4 near_far;    // x: near plane, y: far plane
  vec4 image_size;  // width, height, 1/width, 1/height
} camera;

vec3 materialDiffuse(uint m) {
  return materials[m].diffuse_type.rgb;
}
bool materialIsPhong(uint m) {
  return int(materials[m].diffuse_type.w) == kMaterialPhong;
}
vec3 materialSpecular(uint m) {
  return materials[m].specular_exponent.rgb;
}
float materialExponent(uint m) {
  return materials[m].specular_exponent.w;
}
vec3 materialEmission(uint m) {
  return materials[m].emission.rgb;
}
