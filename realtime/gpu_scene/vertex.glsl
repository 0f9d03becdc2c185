// The vertex attributes of GpuScene::draw (realtime/gpu_scene/gpu_scene.h), at the locations of
// gpu_scene_shared.h.
#include "realtime/gpu_scene/gpu_scene_shared.h"

layout(location = kVertexPositionLocation) in vec3 vertex_position;  // world space
layout(location = kVertexNormalLocation) in vec3 vertex_normal;      // world space, unit, front side
layout(location = kVertexMaterialLocation) in uint vertex_material;  // index into materials[]
// World space, unit, or zero on a flat mesh (shading_normal.glsl interpolates it).
layout(location = kVertexShadingNormalLocation) in vec3 vertex_shading_normal;
