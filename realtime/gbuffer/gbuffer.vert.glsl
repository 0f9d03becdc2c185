#include "realtime/gpu_scene/scene.glsl"
#include "realtime/gpu_scene/vertex.glsl"

#ifdef EXPLICIT_VIEW
// Views other than the camera's (GBuffer::renderViews): a draw's records with base instance i
// draw through view i into viewport i, chosen here where the GL allows, else in
// gbuffer_views.geom.glsl (which then takes these outputs under g_ names).
#include "realtime/gbuffer/gbuffer_views_shared.h"
#include "realtime/gl/binding_plan_shared.h"
// The view's index in its draw: the base instance of its multi-draw records (view_culling.h).
layout(location = kVertexInstanceLocation) in uint vertex_instance;
layout(std140, binding = kGBufferViewsBinding) uniform GBufferViewBlock {
  GBufferViewRecord u_views[kMaxGBufferViewsPerDraw];
};
#ifndef VIEWPORT_FROM_VERTEX_SHADER
#define world_position g_world_position
#define world_normal g_world_normal
#define world_shading_normal g_world_shading_normal
#define material g_material
#define view_eye g_view_eye
#define scene_triangle g_scene_triangle
flat out int g_viewport;
#endif
flat out vec3 view_eye;
#endif
// The triangle's index in the scene's list: its triangles are flat and in list order, and a
// draw's (or a multi-draw record's) gl_VertexID counts from its first vertex.
flat out int scene_triangle;

out vec3 world_position;
flat out vec3 world_normal;
out vec3 world_shading_normal;  // zero on a flat mesh (shading_normal.glsl)
flat out uint material;

void main() {
  world_position = vertex_position;
  world_normal = vertex_normal;
  world_shading_normal = vertex_shading_normal;
  material = vertex_material;
  scene_triangle = gl_VertexID / 3;
#ifdef EXPLICIT_VIEW
  int view = int(vertex_instance);
  view_eye = u_views[view].eye.xyz;
  ivec2 excluded = u_views[view].excluded_triangles.xy;
  if (scene_triangle >= excluded.x && scene_triangle < excluded.y)
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // all three corners beyond x = w: clipped whole
  else
    gl_Position = u_views[view].view_projection * vec4(vertex_position, 1.0);
#ifdef VIEWPORT_FROM_VERTEX_SHADER
  gl_ViewportIndex = view;
#else
  g_viewport = view;
#endif
#else
  gl_Position = camera.view_projection * vec4(vertex_position, 1.0);
#endif
}
