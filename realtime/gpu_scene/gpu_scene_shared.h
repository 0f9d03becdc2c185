// The scene as GpuScene uploads it and shaders read it (gpu_scene/scene.glsl, vertex.glsl): the
// material record of the materials buffer, the camera uniform block and the vertex attributes.
#pragma once
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
namespace gib::rt::gpu {
#endif

// Material types (scene::MaterialType): Lambert and Phong reflect diffusely or glossily; a mirror
// (an ideal specular conductor) and glass (a smooth dielectric) reflect and refract as delta
// distributions, with the Fresnel functions of scene/fresnel_shared.h.
const int kMaterialLambert = 0;
const int kMaterialPhong = 1;
const int kMaterialMirror = 2;
const int kMaterialGlass = 3;

// One record per material in a buffer that shaders read as a buffer texture (RGBA32F, unit
// kMaterialsUnit): material m is texels kMaterialTexels·m + 0 … 5, one per member below. A buffer
// texture, not a storage buffer, because every shading pass reads it per pixel and llvmpipe
// gathers texel fetches across a SIMD row but loads storage buffers lane by lane. Every material
// carries every field (the scene's defaults where its type does not use them), so that one record
// describes the one material model of scene::Material; a shader fetches only the texels it reads.
// The conductor carries n and κ rather than F⊥: shaders that use the approximation of eq. 1.6 get
// F⊥ from fresnelAtNormalIncidence(n, κ), and the exact eq. 1.5 needs n and κ anyway.
const int kMaterialTexels = 6;
struct Material {
  vec4 diffuse_type;         // rgb diffuse reflectance, w: kMaterialLambert … kMaterialGlass
  vec4 specular_exponent;    // rgb specular reflectance, w: Phong exponent n
  vec4 emission;             // rgb radiance emitted from the front side, w unused
  vec4 conductor_n_perfect;  // mirror: rgb real index n, w: 1 for a perfect mirror (R = 1), else 0
  vec4 conductor_k;          // mirror: rgb extinction coefficient κ, w unused
  vec4 absorption_ior;       // glass: rgb Beer–Lambert coefficient per scene unit, w: ior
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
// unit geometric normal (b − a) × (c − a) and its material; a mesh with shading normals
// (scene::Mesh::normals) adds each vertex's own, which a pass interpolates (shading_normal.glsl).
// Two normals, not one, because the geometric one decides a side (which side a viewer or an
// emitter is on: G-buffer views, one-sided emission) where an interpolated normal can be wrong
// near a silhouette, and because it keeps flat meshes' vertices and images as they were.
// AtlasMesh adds its coordinate.
const int kVertexPositionLocation = 0;  // vec3, world space
const int kVertexNormalLocation = 1;    // vec3, world space, unit, front side
const int kVertexMaterialLocation = 2;  // uint, index into the materials
const int kVertexAtlasUvLocation = 3;   // vec2, [0, 1]² of the atlas (AtlasMesh only)
// uint, per instance: the draw's base instance plus gl_InstanceID (GL 4.5 has no
// gl_BaseInstance), which a multi-draw's records use to name their view (view_culling.h).
const int kVertexInstanceLocation = 4;
// Instances a draw of GpuScene may index through kVertexInstanceLocation.
const int kMaxVertexInstances = 256;
// vec3, world space: the mesh's unit shading normal at the vertex (front side's hemisphere), or
// zero on a flat mesh, which every interpolation keeps exactly zero: a pass then takes the
// geometric normal bit for bit. Vertex arrays that do not enable it (AtlasMesh, and GpuScene for a
// scene without shading normals) read GL's default current value of a disabled attribute,
// (0, 0, 0, 1): flat.
const int kVertexShadingNormalLocation = 5;

#ifdef __cplusplus
static_assert(sizeof(Material) == kMaterialTexels * 16, "struct Material: one vec4 per texel");
static_assert(sizeof(Camera) == 3 * 64 + 3 * 16, "std140 block Camera: three mat4, three vec4");
}  // namespace gib::rt::gpu
#endif
