// The scene as GpuScene uploads it and shaders read it (gpu_scene/scene.glsl, vertex.glsl): the
// material record of the materials buffer, the camera uniform block and the vertex attributes.
#pragma once
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
namespace gib::rt::gpu {
#endif

const int kMaterialLambert = 0;
const int kMaterialPhong = 1;

// One record per material in a buffer that shaders read as a buffer texture (RGBA32F, unit
// kMaterialsUnit): material m is texels kMaterialTexels·m + 0, 1, 2. A buffer texture, not a
// storage buffer, because every shading pass reads it per pixel and llvmpipe gathers texel
// fetches across a SIMD row but loads storage buffers lane by lane.
const int kMaterialTexels = 3;
struct Material {
  vec4 diffuse_type;       // rgb diffuse reflectance, w: kMaterialLambert or kMaterialPhong
  vec4 specular_exponent;  // rgb specular reflectance, w: Phong exponent n
  vec4 emission;           // rgb radiance emitted from the front side, w unused
};

// std140, binding kCameraBinding: the pinhole camera of scene::cameraRayDirection (see
// gib::rt::cameraTransform).
struct Camera {
  mat4 view_projection;
  mat4 view;
  mat4 projection;
  vec4 position;    // xyz: eye, w 1
  vec4 near_far;    // x: near plane, y: far plane
  vec4 image_size;  // width, height, 1/width, 1/height
};

// Vertex attributes of GpuScene::draw: flat triangles, so every vertex carries its triangle's
// unit geometric normal (b − a) × (c − a) and its material. AtlasMesh adds its coordinate.
const int kVertexPositionLocation = 0;  // vec3, world space
const int kVertexNormalLocation = 1;    // vec3, world space, unit, front side
const int kVertexMaterialLocation = 2;  // uint, index into the materials
const int kVertexAtlasUvLocation = 3;   // vec2, [0, 1]² of the atlas (AtlasMesh only)
// uint, per instance: the draw's base instance plus gl_InstanceID (GL 4.5 has no
// gl_BaseInstance), which a multi-draw's records use to name their view (view_culling.h).
const int kVertexInstanceLocation = 4;
// Instances a draw of GpuScene may index through kVertexInstanceLocation.
const int kMaxVertexInstances = 256;

#ifdef __cplusplus
static_assert(sizeof(Material) == 48, "std430 struct Material: three vec4");
static_assert(sizeof(Camera) == 3 * 64 + 3 * 16, "std140 block Camera: three mat4, three vec4");
}  // namespace gib::rt::gpu
#endif
