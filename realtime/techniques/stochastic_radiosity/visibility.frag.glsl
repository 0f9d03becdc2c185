// The distance from the shooter of the surface seen in this direction. With the hemispherical
// projection the interpolated point is not the one seen along the texel's direction when a
// triangle is large: that is the paper's tessellation caveat, left visible on purpose.
in vec3 v_local;
layout(location = 0) out float o_distance;

void main() {
  o_distance = length(v_local);
}
