// Coverage images of hardware light sampling: the light's and occluders' triangles, pulled from
// the coverage buffer by vertex index, seen from the point. One point per draw (the bench test,
// `u_point_position`), or one point per instance, each into its own layer: the G-buffer pixels
// u_first_point + instance (GBUFFER_POINTS, the technique).
#include "realtime/techniques/jittered_light_sampling/coverage_view.glsl"
#ifdef GBUFFER_POINTS
#include "realtime/techniques/jittered_light_sampling/gbuffer_point.glsl"
uniform int u_first_point;
#else
uniform vec3 u_point_position;
uniform uint u_point;
#endif
flat out int g_layer;
flat out uint g_point;

void main() {
#ifdef GBUFFER_POINTS
  g_layer = gl_InstanceID;
  g_point = uint(u_first_point + gl_InstanceID);
  vec3 x;
  bool lit = gbufferPoint(int(g_point), x);
#else
  g_layer = 0;
  g_point = u_point;
  vec3 x = u_point_position;
  bool lit = true;
#endif
  CoverageView view;
  // A point that cannot see the light draws nothing (w = 0: the geometry shader drops it).
  gl_Position = lit && coverageView(x, view) ? coverageClip(view, corners[gl_VertexID].xyz)
                                             : vec4(0.0);
}
