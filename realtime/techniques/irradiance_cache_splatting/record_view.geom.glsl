// Passes each triangle of a record view to its layer.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec2 g_atlas_uv[];
in vec3 g_world[];
flat in vec3 g_origin[];
flat in int g_layer[];
in gl_PerVertex {
  vec4 gl_Position;
  float gl_ClipDistance[1];
}
gl_in[];
out vec2 v_atlas_uv;
out vec3 v_world;
flat out vec3 v_origin;
out gl_PerVertex {
  vec4 gl_Position;
  float gl_ClipDistance[1];
};

void main() {
  for (int i = 0; i < 3; ++i) {
    gl_Layer = g_layer[0];
    gl_Position = gl_in[i].gl_Position;
    gl_ClipDistance[0] = gl_in[i].gl_ClipDistance[0];
    v_atlas_uv = g_atlas_uv[i];
    v_world = g_world[i];
    v_origin = g_origin[0];
    EmitVertex();
  }
  EndPrimitive();
}
