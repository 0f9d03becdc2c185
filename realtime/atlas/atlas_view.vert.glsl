// A camera view of the atlas techniques (the radiosity estimate, the light path maps' indirect
// light; Barsi & Jakab §3.3): the scene with its atlas coordinates, for bilinear atlas lookups.
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/atlas/atlas_vertex.glsl"

out vec2 v_atlas_uv;
out vec3 v_world;
flat out vec3 v_normal;

void main() {
  v_atlas_uv = vertex_atlas_uv;
  v_world = vertex_position;
  v_normal = vertex_normal;
  gl_Position = camera.view_projection * vec4(vertex_position, 1.0);
}
