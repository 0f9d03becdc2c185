// Layered visibility maps where the vertex shader cannot select the layer: each triangle passed
// through to the hemicube face its instance draws (visibility.vert.glsl), clip distance included.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec3 g_local[];
flat in int g_layer[];
out vec3 v_local;

void main() {
  for (int i = 0; i < 3; ++i) {
    gl_Layer = g_layer[0];
    gl_Position = gl_in[i].gl_Position;
    gl_ClipDistance[0] = gl_in[i].gl_ClipDistance[0];
    v_local = g_local[i];
    EmitVertex();
  }
  EndPrimitive();
}
