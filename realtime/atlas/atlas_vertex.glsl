// The vertex attributes of AtlasMesh::draw (realtime/atlas/atlas_mesh.h): the scene's attributes
// plus each vertex's atlas coordinate.
#include "realtime/gpu_scene/vertex.glsl"
layout(location = kVertexAtlasUvLocation) in vec2 vertex_atlas_uv;  // [0, 1]², GL texel rows (y up)
