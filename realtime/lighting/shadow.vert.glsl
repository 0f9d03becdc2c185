// Shadow map generation (book §4.1.1): the scene seen from the light.
#include "realtime/gpu_scene/vertex.glsl"
uniform mat4 u_face_view_projection;  // this cube face, or the orthographic map
out vec3 v_world;

void main() {
  v_world = vertex_position;
  gl_Position = u_face_view_projection * vec4(vertex_position, 1.0);
}
