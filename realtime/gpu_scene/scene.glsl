// The scene as GpuScene (realtime/gpu_scene/gpu_scene.h) uploads it: materials in a storage
// buffer and the camera in a uniform block, both declared once in gpu_scene_shared.h. Vertex
// attributes: vertex.glsl.
#include "realtime/gpu_scene/gpu_scene_shared.h"

layout(std430, binding = kMaterialsBinding) readonly buffer Materials {
  Material materials[];
};

layout(std140, binding = kCameraBinding) uniform CameraBlock {
  Camera camera;
};

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
