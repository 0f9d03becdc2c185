// Passes each triangle to its layer (the vertex shader's: a gather point's view, or a slab's
// face), with its clip distances.
#include "realtime/techniques/hemispherical_gather/hemispherical_gather_shared.h"
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec2 g_atlas_uv[];
in vec3 g_world[];
flat in vec3 g_normal[];
flat in int g_layer[];
in gl_PerVertex {
  vec4 gl_Position;
  float gl_ClipDistance[kGatherClipDistances];
}
gl_in[];
out vec2 v_atlas_uv;
out vec3 v_world;
flat out vec3 v_normal;
out gl_PerVertex {
  vec4 gl_Position;
  float gl_ClipDistance[kGatherClipDistances];
};

void main() {
  for (int i = 0; i < 3; ++i) {
    gl_Layer = g_layer[0];
    gl_Position = gl_in[i].gl_Position;
    for (int k = 0; k < kGatherClipDistances; ++k) gl_ClipDistance[k] = gl_in[i].gl_ClipDistance[k];
    v_atlas_uv = g_atlas_uv[i];
    v_world = g_world[i];
    v_normal = g_normal[0];
    EmitVertex();
  }
  EndPrimitive();
}
