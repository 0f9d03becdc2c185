// Draws the scene into the shooter's visibility map (visibility_projection.glsl). The distance
// from the shooter goes into the colour (visibility.frag.glsl); the depth test keeps the nearest.
// HEMICUBE: one instanced draw, instance f drawing hemicube face f into layer f of a layered
// framebuffer (the layer chosen here where the GL allows, else in visibility.geom.glsl).
#include "realtime/atlas/atlas_vertex.glsl"
#include "realtime/techniques/stochastic_radiosity/shooter.glsl"
#include "realtime/techniques/stochastic_radiosity/visibility_projection.glsl"

uniform float u_near;
uniform float u_far;

// Without vertex-shader layers the outputs go to visibility.geom.glsl under g_ names.
#ifndef LAYER_FROM_VERTEX_SHADER
#define v_local g_local
flat out int g_layer;
#endif
out vec3 v_local;

void main() {
  ShooterFrame frame = shooterFrame();
  vec3 l = shooterLocal(frame, vertex_position);
  v_local = l;
#ifdef HEMICUBE
  int face = gl_InstanceID;
  vec3 c = hemicubeFaceCoordinates(l, face);
  // Perspective depth between the near and far planes along the face's axis.
  float a = (u_far + u_near) / (u_far - u_near), b = -2.0 * u_far * u_near / (u_far - u_near);
  gl_Position = vec4(c.x, c.y, a * c.z + b, c.z);
  gl_ClipDistance[0] = 1.0;
  if (face != 0) {
    // A side face's half (NDC y over [−w, w]) goes to the layer's lower rows, NDC y over
    // [−w, 0], and what lies beyond its top (y > w) is clipped: the rows a half viewport gave.
    gl_Position.y = 0.5 * (c.y - c.z);
    gl_ClipDistance[0] = c.z - c.y;
  }
#ifdef LAYER_FROM_VERTEX_SHADER
  gl_Layer = face;
#else
  g_layer = face;
#endif
#else
  // Barsi & Jakab's vertex program: (x, y) of the unit direction, depth linear in the distance;
  // the half-space behind the shooter is clipped (their program folds it onto the disk).
  float d = length(l);
  gl_Position = vec4(hemisphereCoordinates(l), 2.0 * (d - u_near) / (u_far - u_near) - 1.0, 1.0);
  gl_ClipDistance[0] = l.z;
#ifndef LAYER_FROM_VERTEX_SHADER
  g_layer = 0;
#endif
#endif
}
