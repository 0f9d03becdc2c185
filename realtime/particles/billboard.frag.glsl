// A particle's fragment: the eye ray through the pixel (exactly, where the book takes rays
// parallel to the view axis) meets the particle's sphere on a segment; its optical depth gives the
// opacity α and the fragment blends α·S over what lies behind (S: the particle's radiance towards
// the eye per unit opacity, view_shading.comp.glsl), premultiplied, back to front.
//
// Spherical billboards (§9.3.1) clip the segment against the surfaces' depth and the near plane,
// so a particle fades smoothly into an object and into the camera. Planar billboards keep the
// whole segment and are depth-tested at the quad through the centre facing the camera, as a
// classic billboard is: the clipping artefact of Fig. 9.3 where a particle meets a surface.
#include "realtime/gbuffer/gbuffer_maps.glsl"
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/particles/particle_medium.glsl"

layout(std430, binding = kParticleSourceBinding) readonly buffer Source {
  vec4 source[];
};
uniform mat4 u_inverse_view_projection;  // clip space to world, for the pixel's ray
uniform bool u_spherical;
uniform int u_opacity;  // kOpacityLinear, kOpacityGouraud or kOpacityHomogeneous
flat in int v_particle;
layout(location = 0) out vec4 o_radiance;

void main() {
  vec4 sphere = particles[v_particle].centre_radius;
  float tau = particles[v_particle].density.x;
  vec3 eye = camera.position.xyz;
  vec2 ndc = 2.0 * gl_FragCoord.xy * camera.image_size.zw - 1.0;
  vec4 far_point = u_inverse_view_projection * vec4(ndc, 1.0, 1.0);
  vec3 direction = normalize(far_point.xyz / far_point.w - eye);

  vec3 to_centre = sphere.xyz - eye;
  float t_centre = dot(to_centre, direction);
  float d2 = dot(to_centre, to_centre) - t_centre * t_centre;
  if (d2 >= sphere.w * sphere.w) discard;
  float d = sqrt(max(d2, 0.0));
  float half_chord = sqrt(sphere.w * sphere.w - d2);
  float t0 = t_centre - half_chord, t1 = t_centre + half_chord;

  // The surface behind the pixel (the ray distance of the G-buffer, none: background) and the
  // near plane along this ray.
  vec4 surface = texelFetch(u_gbuffer_position, ivec2(gl_FragCoord.xy), 0);
  float t_surface = surface.w >= 0.0 ? surface.w : 3.0e38;
  vec3 forward = -vec3(camera.view[0][2], camera.view[1][2], camera.view[2][2]);
  float t_near = camera.near_far.x / dot(direction, forward);
  if (u_spherical) {
    t0 = max(t0, t_near);
    t1 = min(t1, t_surface);
  } else {
    float t_quad = dot(to_centre, forward) / dot(direction, forward);
    if (t_quad > t_surface || t_quad < t_near) discard;
  }
  if (t1 <= t0) discard;

  float depth;
  if (u_opacity == kOpacityLinear)
    depth = chordOpticalDepth(tau, sphere.w, d, t0 - t_centre, t1 - t_centre);
  else if (u_opacity == kOpacityGouraud)
    depth = tau * (1.0 - d / sphere.w) * (t1 - t0);
  else
    depth = tau * (t1 - t0);
  float alpha = 1.0 - exp(-depth);
  o_radiance = vec4(alpha * source[v_particle].rgb, alpha);
}
