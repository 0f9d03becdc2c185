// Every texture unit, image unit and buffer binding point the realtime layer uses, in one table,
// so that the building blocks a technique combines (G-buffer, shadow maps, atlas, scene buffers)
// never share a slot, and a technique's own slots come from a range that none of them uses.
// Techniques declare their slots in their own `<name>_shared.h` as offsets into these ranges.
#pragma once
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
namespace gib::rt::gpu {
#endif

// Texture units (sampler bindings).
const int kGBufferPositionUnit = 0;  // gbuffer/: world position, w ray distance
const int kGBufferNormalUnit = 1;    // gbuffer/: geometric normal, w material
const int kShadowMapUnit = 2;        // lighting/: the current batch's shadow maps (an array)
const int kAddedImageUnit = 3;       // gl/: the image add_image.frag.glsl adds into a frame
const int kTechniqueFirstUnit = 4;   // 4..7: a technique's own textures
const int kTechniqueUnitCount = 4;
const int kAtlasPositionUnit = 8;       // atlas/: xyz sample point, w 1 inside a chart
const int kAtlasNormalUnit = 9;         // atlas/: xyz unit normal, w world area of the texel
const int kAtlasAlbedoUnit = 10;        // atlas/: rgb diffuse reflectance
const int kAtlasEmissionUnit = 11;      // atlas/: rgb emitted radiance, front side
const int kMaterialsUnit = 12;          // gpu_scene/: the scene's materials, a buffer texture
const int kPeelLayersUnit = 13;         // depth_peeling/: the layers of one bundle, an array
const int kPeelPreviousDepthUnit = 14;  // depth_peeling/: the depth of the layer peeled last
// ray_casting/: a structure's buffer textures (ray_casting_shared.h). Past GL 4.5's guaranteed 16
// units per stage; rt::checkRayCastingLimits checks the driver offers them (Mesa and NVIDIA: 32).
const int kRayTrianglesUnit = 15;  // the triangles' IVMs and apexes, then the slots' indices
const int kRayNodesUnit = 16;      // the structure's nodes
const int kRayFlagsUnit = 17;      // the loose kd-tree's node flags
// distance_map/: the distance maps (a cube-map array: rgb radiance, a distance from the
// reference point; distance_map_shared.h) and, while they are composed, their views' light and
// triangle codes (GBuffer::albedo's w).
const int kDistanceMapUnit = 18;
const int kDistanceMapLightUnit = 19;
const int kDistanceMapCodeUnit = 20;
// lighting/: the scene's environment map (book §4.2), a latitude-longitude RGB texture
// (environment_texture.h): the background the emission pass shows and what techniques that
// light by it read.
const int kEnvironmentUnit = 21;

// Image units of compute passes (one program at a time reads one image and writes another, or
// several: units kImageDestinationUnit and up, at most 4 of them, GL 4.5 offering 8).
const int kImageSourceUnit = 0;
const int kImageDestinationUnit = 1;

// Shader storage buffer bindings.
const int kTechniqueFirstStorageBinding = 1;  // 1..5: a technique's own buffers
const int kTechniqueStorageBindingCount = 5;
const int kTestFirstStorageBinding = 6;  // 6, 7: tests' query and result buffers

// Uniform buffer bindings.
const int kCameraBinding = 0;                 // gpu_scene/: the camera block
const int kLightSamplesBinding = 1;           // lighting/: the current batch of light samples
const int kShadowFacesBinding = 2;            // lighting/: the layers a batch's shadow pass draws
const int kGBufferViewsBinding = 3;           // gbuffer/: the views of one instanced G-buffer draw
const int kDistanceMapObjectsBinding = 6;     // distance_map/: the maps' objects and settings
const int kTechniqueFirstUniformBinding = 4;  // 4, 5: a technique's own blocks
const int kTechniqueUniformBindingCount = 2;

#ifdef __cplusplus
}  // namespace gib::rt::gpu
#endif
