#include "realtime/gpu_scene/scene.glsl"
#include "realtime/gpu_scene/vertex.glsl"

#ifdef EXPLICIT_VIEW
uniform mat4 u_view_projection;  // a view other than the camera's (GBuffer::renderViews)
#endif

out vec3 world_position;
flat out vec3 world_normal;
flat out uint material;

void main() {
  world_position = vertex_position;
  world_normal = vertex_normal;
  material = vertex_material;
#ifdef EXPLICIT_VIEW
  gl_Position = u_view_projection * vec4(vertex_position, 1.0);
#else
  gl_Position = camera.view_projection * vec4(vertex_position, 1.0);
#endif
}
