// The voxel slices' pass of a gather view: a triangle over the whole layer of each gather point
// of the batch (instance), for the fragment shader to trace the slices (gather_slices.frag.glsl).
#include "realtime/techniques/hemispherical_gather/layered_vertex_outputs.glsl"

void main() {
  vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
  g_atlas_uv = vec2(0.0);
  g_world = vec3(0.0);
  g_normal = vec3(0.0);
  g_layer = gl_InstanceID;
  for (int i = 0; i < kGatherClipDistances; ++i) gl_ClipDistance[i] = 1.0;
}
