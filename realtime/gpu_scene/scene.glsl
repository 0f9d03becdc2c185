// The scene as GpuScene (realtime/gpu_scene/gpu_scene.h) uploads it: materials in a buffer
// texture and the camera in a uniform block, both declared once in gpu_scene_shared.h. Vertex
// attributes: vertex.glsl.
#include "realtime/gpu_scene/gpu_scene_shared.h"

layout(binding = kMaterialsUnit) uniform samplerBuffer u_materials;  // struct Material, 6 texels each

layout(std140, binding = kCameraBinding) uniform CameraBlock {
  Camera camera;
};

// field: the member of struct Material, in order (0 diffuse_type … 5 absorption_ior).
vec4 materialTexel(uint m, int field) {
  return texelFetch(u_materials, kMaterialTexels * int(m) + field);
}
int materialType(uint m) {  // kMaterialLambert … kMaterialGlass
  return int(materialTexel(m, 0).w);
}
vec3 materialDiffuse(uint m) {
  return materialTexel(m, 0).rgb;
}
bool materialIsPhong(uint m) {
  return materialType(m) == kMaterialPhong;
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
// Mirror: the conductor's complex index n + iκ per channel (fresnelConductor,
// fresnelAtNormalIncidence of scene/fresnel_shared.h), or a perfect reflector (R = 1).
vec3 materialConductorN(uint m) {
  return materialTexel(m, 3).rgb;
}
bool materialIsPerfectMirror(uint m) {
  return materialTexel(m, 3).w != 0.0;
}
vec3 materialConductorK(uint m) {
  return materialTexel(m, 4).rgb;
}
// Glass: the index of refraction against the outside (index 1), and the Beer–Lambert
// coefficient inside, per channel and scene unit.
float materialIor(uint m) {
  return materialTexel(m, 5).w;
}
vec3 materialAbsorption(uint m) {
  return materialTexel(m, 5).rgb;
}
