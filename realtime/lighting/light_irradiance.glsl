// The irradiance one light sample (point or directional; light_space.glsl's uniforms) delivers to
// a point, on a plane facing the light, and the direction towards the light. Shared by every
// pass that shades with light samples (direct's deferred shading, the radiosity atlas's light
// injection), so they agree on the spot cone and falloff.
uniform vec3 u_light_intensity;
uniform float u_cos_cone;
uniform float u_exponent;
// Added to the squared distance of a point sample: 0 for a light that is a point; a virtual light
// that stands for a patch (light path maps) gives the patch's area over π, which keeps its
// irradiance on a receiver beside it finite (the on-axis irradiance of a disk of that area).
uniform float u_distance_squared_offset;

// False outside a spot light's cone (no light at all).
bool lightSampleIrradiance(vec3 p, out vec3 wi, out vec3 irradiance) {
#ifdef POINT_LIGHT
  vec3 to_light = u_light_position - p;
  float distance_squared = dot(to_light, to_light);
  wi = to_light * inversesqrt(distance_squared);
  float cos_axis = dot(-wi, u_light_axis);
  if (cos_axis < u_cos_cone) return false;
  float falloff = u_exponent == 0.0 ? 1.0 : pow(max(cos_axis, 0.0), u_exponent);
  irradiance = u_light_intensity * (falloff / (distance_squared + u_distance_squared_offset));
#else
  wi = -u_light_axis;
  irradiance = u_light_intensity;
#endif
  return true;
}
