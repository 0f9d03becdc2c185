// Draws the scene into the shooter's visibility map (visibility_projection.glsl). The distance
// from the shooter goes into the colour (visibility.frag.glsl); the depth test keeps the nearest.
#include "realtime/atlas/atlas_vertex.glsl"
#include "realtime/techniques/stochastic_radiosity/shooter.glsl"
#include "realtime/techniques/stochastic_radiosity/visibility_projection.glsl"

uniform float u_near;
uniform float u_far;
#ifdef HEMICUBE
uniform int u_face;
#endif
out vec3 v_local;

void main() {
  ShooterFrame frame = shooterFrame();
  vec3 l = shooterLocal(frame, vertex_position);
  v_local = l;
#ifdef HEMICUBE
  vec3 c = hemicubeFaceCoordinates(l, u_face);
  // Perspective depth between the near and far planes along the face's axis.
  float a = (u_far + u_near) / (u_far - u_near), b = -2.0 * u_far * u_near / (u_far - u_near);
  gl_Position = vec4(c.x, c.y, a * c.z + b, c.z);
  gl_ClipDistance[0] = 1.0;
#else
  // Barsi & Jakab's vertex program: (x, y) of the unit direction, depth linear in the distance;
  // the half-space behind the shooter is clipped (their program folds it onto the disk).
  float d = length(l);
  gl_Position = vec4(hemisphereCoordinates(l), 2.0 * (d - u_near) / (u_far - u_near) - 1.0, 1.0);
  gl_ClipDistance[0] = l.z;
#endif
}
