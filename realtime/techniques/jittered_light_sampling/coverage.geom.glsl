// Stands in for the paper's dilated triangles (§4.2.1): a fragment program cannot make fragments
// the rasterizer did not, so each triangle is drawn as its pixel bounding box grown by one pixel,
// and the fragment shader tests its samples against the original triangle, handed over in pixel
// units with the plane of its window depth. The caller keeps every vertex in front of the point.
layout(triangles) in;
layout(triangle_strip, max_vertices = 4) out;
uniform int u_size;  // the coverage image is u_size × u_size pixels
flat out vec2 v_a;
flat out vec2 v_b;
flat out vec2 v_c;
flat out vec3 v_depth_plane;  // depth = v_depth_plane.z + dot(v_depth_plane.xy, pixel − v_a)

void main() {
  vec4 c0 = gl_in[0].gl_Position, c1 = gl_in[1].gl_Position, c2 = gl_in[2].gl_Position;
  if (c0.w <= 0.0 || c1.w <= 0.0 || c2.w <= 0.0) return;
  vec2 s0 = (c0.xy / c0.w * 0.5 + 0.5) * float(u_size);
  vec2 s1 = (c1.xy / c1.w * 0.5 + 0.5) * float(u_size);
  vec2 s2 = (c2.xy / c2.w * 0.5 + 0.5) * float(u_size);
  vec2 e1 = s1 - s0, e2 = s2 - s0;
  float area = e1.x * e2.y - e1.y * e2.x;
  if (abs(area) < 1e-9) return;  // seen edge on: covers no sample
  // Window depth is affine in window coordinates: solve for its gradient.
  float z0 = c0.z / c0.w * 0.5 + 0.5;
  float dz1 = c1.z / c1.w * 0.5 + 0.5 - z0, dz2 = c2.z / c2.w * 0.5 + 0.5 - z0;
  vec2 gradient = vec2(dz1 * e2.y - dz2 * e1.y, dz2 * e1.x - dz1 * e2.x) / area;
  vec2 lo = clamp(floor(min(s0, min(s1, s2))) - 1.0, vec2(0.0), vec2(u_size));
  vec2 hi = clamp(ceil(max(s0, max(s1, s2))) + 1.0, vec2(0.0), vec2(u_size));
  if (any(greaterThanEqual(lo, hi))) return;
  vec2 corners[4] = vec2[](lo, vec2(hi.x, lo.y), vec2(lo.x, hi.y), hi);
  for (int i = 0; i < 4; ++i) {
    v_a = s0;
    v_b = s1;
    v_c = s2;
    v_depth_plane = vec3(gradient, z0);
    gl_Position = vec4(corners[i] / float(u_size) * 2.0 - 1.0, 0.0, 1.0);
    EmitVertex();
  }
  EndPrimitive();
}
