// Shadow map generation (book §4.1.1): the scene seen from the light.
layout(location = 0) in vec3 a_position;
uniform mat4 u_face_view_projection;  // this cube face, or the orthographic map
out vec3 v_world;

void main() {
  v_world = a_position;
  gl_Position = u_face_view_projection * vec4(a_position, 1.0);
}
