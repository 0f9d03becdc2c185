// The technique's points are the camera G-buffer's pixels, numbered row by row from GL's bottom
// row: the surface there, lifted a hair off it towards the viewer so that its own triangle lies
// behind the point's near plane. Shared by the coverage draw and the weighting pass, so both see
// the same point.
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/techniques/jittered_light_sampling/coverage_view.glsl"
#include "realtime/gbuffer/shaded_surface.glsl"

uniform int u_point_count;  // the G-buffer's pixels
uniform int u_gbuffer_width;
uniform float u_lift;
uniform vec3 u_emitting_side;  // the light's front normal: it emits to that side only

ivec2 gbufferPixel(int point) {
  return ivec2(point % u_gbuffer_width, point / u_gbuffer_width);
}

// False where the pixel saw nothing, or a surface on the light's back side.
bool gbufferSurface(int point, out ShadedSurface s, out vec3 x) {
  if (point >= u_point_count || !shadedSurface(gbufferPixel(point), s)) return false;
  x = s.p + u_lift * s.n;
  return dot(x - corners[0].xyz, u_emitting_side) > 0.0;
}

bool gbufferPoint(int point, out vec3 x) {
  ShadedSurface s;
  return gbufferSurface(point, s, x);
}
