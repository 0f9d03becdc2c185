#include "scene/scene.glsl"
#include "scene/vertex.glsl"

out vec3 world_position;
flat out vec3 world_normal;
flat out uint material;

void main() {
  world_position = vertex_position;
  world_normal = vertex_normal;
  material = vertex_material;
  gl_Position = camera.view_projection * vec4(vertex_position, 1.0);
}
