// Shadow map generation (book §4.1.1): the scene seen from the light, every layer of a batch in
// one multi-draw (records with base instance i draw shadow face i into its layer, each only the
// triangles the face may see: view_culling.h). The layer is written here
// where the GL has vertex-shader layer selection (ARB_shader_viewport_layer_array or
// AMD_vertex_shader_layer), else by shadow.geom.glsl.
#include "realtime/gpu_scene/vertex.glsl"
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/lighting/light_space.glsl"

layout(std140, binding = kShadowFacesBinding) uniform ShadowFaceBlock {
  ShadowFace u_shadow_faces[kMaxShadowFaces];
};
// Without vertex-shader layers the outputs go to shadow.geom.glsl under g_ names.
#ifndef LAYER_FROM_VERTEX_SHADER
#define v_world g_world
#define v_slot g_slot
flat out int g_layer;
#endif
out vec3 v_world;
flat out int v_slot;

// The face's index in the batch: its records' base instance.
layout(location = kVertexInstanceLocation) in uint vertex_instance;

void main() {
  int face = int(vertex_instance);
  ivec4 layer_slot = u_shadow_faces[face].layer_slot;
  gl_Position = u_shadow_faces[face].view_projection * vec4(vertex_position, 1.0);
  // A point sample whose cone is at most a hemisphere lights nothing behind the plane through it
  // across its axis, and no lit point's shadow ray crosses that plane: what lies behind is not
  // drawn (half of each side face of a cube around a point on an area light).
  gl_ClipDistance[0] = 1.0;
#ifdef POINT_LIGHT
  GpuLightSample light = u_light_samples[layer_slot.y];
  if (light.axis.w >= 0.0)
    gl_ClipDistance[0] = dot(vertex_position - light.position.xyz, light.axis.xyz);
#endif
  v_world = vertex_position;
  v_slot = layer_slot.y;
#ifdef LAYER_FROM_VERTEX_SHADER
  gl_Layer = layer_slot.x;
#else
  g_layer = layer_slot.x;
#endif
}
