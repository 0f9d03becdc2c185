// Layered shadow rendering where the vertex shader cannot select the layer: each triangle passed
// through to the layer its instance's face names (shadow.vert.glsl), clip distance included.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec3 g_world[];
flat in int g_slot[];
flat in int g_layer[];
out vec3 v_world;
flat out int v_slot;

void main() {
  for (int i = 0; i < 3; ++i) {
    gl_Layer = g_layer[0];
    gl_Position = gl_in[i].gl_Position;
    gl_ClipDistance[0] = gl_in[i].gl_ClipDistance[0];
    v_world = g_world[i];
    v_slot = g_slot[0];
    EmitVertex();
  }
  EndPrimitive();
}
