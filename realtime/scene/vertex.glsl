// The vertex attributes of GpuScene::draw (realtime/gpu_scene.h): flat triangles, so every
// vertex carries its triangle's unit geometric normal (b − a) × (c − a) and its material.

layout(location = 0) in vec3 vertex_position;  // world space
layout(location = 1) in vec3 vertex_normal;    // world space, unit, front side
layout(location = 2) in uint vertex_material;  // index into materials[]
