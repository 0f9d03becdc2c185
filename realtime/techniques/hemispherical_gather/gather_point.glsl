// The gather points: one G-buffer pixel at the centre of every spacing × spacing cell of the
// camera image (GL rows from the bottom), its surface lifted a hair off along the normal on the
// viewer's side, and the tangent frame the gather view is built on.
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/gbuffer/shaded_surface.glsl"

uniform ivec2 u_grid;  // gather points across and up
uniform int u_spacing;
uniform float u_lift;

ivec2 gatherPixel(ivec2 cell) {
  return cell * u_spacing + u_spacing / 2;
}

struct GatherFrame {
  vec3 origin;
  vec3 t, b, n;  // tangent, bitangent, normal (right-handed)
};

// False for a cell beyond the grid or a pixel that saw nothing.
bool gatherFrame(int point, out GatherFrame f) {
  if (point >= u_grid.x * u_grid.y) return false;
  ShadedSurface s;
  if (!shadedSurface(gatherPixel(ivec2(point % u_grid.x, point / u_grid.x)), s)) return false;
  f.n = s.n;
  f.origin = s.p + u_lift * s.n;
  // Duff et al.'s branchless orthonormal basis.
  float sign = f.n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (sign + f.n.z);
  float b = f.n.x * f.n.y * a;
  f.t = vec3(1.0 + sign * f.n.x * f.n.x * a, sign * b, -sign * f.n.x);
  f.b = vec3(b, sign + f.n.y * f.n.y * a, -f.n.y);
  return true;
}
