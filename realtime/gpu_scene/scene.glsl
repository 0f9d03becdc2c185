// The scene as GpuScene (realtime/gpu_scene/gpu_scene.h) uploads it: materials in a buffer
// texture and the camera in a uniform block, both declared once in gpu_scene_shared.h. Vertex
// attributes: vertex.glsl.
#include "realtime/gpu_scene/gpu_scene_shared.h"

layout(binding = kMaterialsUnit) uniform samplerBuffer u_materials;  // struct Material, 3 texels each

layout(std140, binding = kCameraBinding) uniform CameraBlock {
  Camera camera;
};

vec4 materialTexel(uint m, int field) {  // field: 0 diffuse_type, 1 specular_exponent, 2 emission
  return texelFetch(u_materials, kMaterialTexels * int(m) + field);
}
vec3 materialDiffuse(uint m) {
  return materialTexel(m, 0).rgb;
}
bool materialIsPhong(uint m) {
  return int(materialTexel(m, 0).w) == kMaterialPhong;
}
vec3 materialSpecular(uint m) {
  return materialTexel(m, 1).rgb;
}
float materialExponent(uint m) {
  return materialTexel(m, 1).w;
}
vec3 materialEmission(uint m) {
  return materialTexel(m, 2).rgb;
}
