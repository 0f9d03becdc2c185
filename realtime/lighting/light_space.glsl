// Where a world point lies in the current light's shadow map, shared by the shadow pass (which
// writes it) and the shading pass (which compares against it). POINT_LIGHT: a cube map around
// u_light_position with 90° faces from u_near to u_far; otherwise an orthographic map along
// u_light_axis through u_light_view_projection, depth 0..1 over the scene's bounding sphere.
uniform vec3 u_light_position;
uniform vec3 u_light_axis;
uniform mat4 u_light_view_projection;
uniform float u_near;
uniform float u_far;

// The distance the variance shadow map stores, scaled to about 0..1 for float precision.
float lightDistance(vec3 p) {
#ifdef POINT_LIGHT
  return length(p - u_light_position) / u_far;
#else
  return (u_light_view_projection * vec4(p, 1.0)).z * 0.5 + 0.5;
#endif
}
