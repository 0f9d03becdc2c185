// The surface a deferred shading pass shades at its pixel: what the G-buffer holds there, with
// the normal on the viewer's side and the direction to the viewer. Needs gpu_scene/scene.glsl.
//
// Probe views (GBuffer::renderViews) store normals turned towards their own eye, which a
// full-screen pass does not know: it then takes ωo along the normal, exact for Lambert surfaces
// and, for Phong, the lobe's value at normal viewing (an approximation the irradiance volume
// accepts).
#include "realtime/gbuffer/gbuffer_maps.glsl"

uniform bool u_normals_face_viewer;

struct ShadedSurface {
  vec3 p;   // world position
  vec3 n;   // unit normal on the viewer's side (reflection is two-sided)
  vec3 wo;  // unit direction to the viewer
  uint material;
};

// False where the pixel saw no surface.
bool shadedSurface(ivec2 pixel, out ShadedSurface s) {
  vec4 position = texelFetch(u_gbuffer_position, pixel, 0);
  if (position.w < 0.0) return false;
  vec4 normal_material = texelFetch(u_gbuffer_normal, pixel, 0);
  s.material = uint(normal_material.w);
  s.p = position.xyz;
  s.n = normal_material.xyz;
  s.wo = s.n;
  if (!u_normals_face_viewer) {
    s.wo = normalize(camera.position.xyz - s.p);
    if (dot(s.n, s.wo) < 0.0) s.n = -s.n;
  }
  return true;
}
