// The vertex attributes of AtlasMesh::draw (realtime/atlas/atlas_mesh.h): the scene's attributes
// plus each vertex's atlas coordinate.
#include "scene/vertex.glsl"
layout(location = 3) in vec2 vertex_atlas_uv;  // [0, 1]², GL texel rows (y upwards)
