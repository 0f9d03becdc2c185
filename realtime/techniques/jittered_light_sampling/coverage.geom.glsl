// The paper's dilated triangles (§4.2.1): a fragment program cannot make fragments the
// rasterizer did not, so each triangle is drawn grown until it covers every pixel it touches (each
// edge pushed out by the half-extent of a pixel along its normal, then clipped to its bounding
// box grown by a pixel, which bounds the long corners of thin triangles), and the fragment shader
// tests its samples against the triangle itself, handed over in pixel units with the plane of
// its window depth. Triangles are first clipped to the near plane (an
// occluder may reach behind the point: a wall beside it), which leaves up to four corners: two
// triangles.
layout(triangles) in;
layout(triangle_strip, max_vertices = 14) out;
uniform int u_size;  // the coverage image is u_size × u_size pixels
flat in int g_layer[];
flat in uint g_point[];
flat out vec2 v_a;
flat out vec2 v_b;
flat out vec2 v_c;
flat out vec3 v_depth_plane;  // depth = v_depth_plane.z + dot(v_depth_plane.xy, pixel − v_a)
flat out uint v_point;

vec2 window(vec4 c) {
  return (c.xy / c.w * 0.5 + 0.5) * float(u_size);
}
float windowDepth(vec4 c) {
  return c.z / c.w * 0.5 + 0.5;
}

void emitTriangle(vec4 c0, vec4 c1, vec4 c2) {
  vec2 s0 = window(c0), s1 = window(c1), s2 = window(c2);
  vec2 e1 = s1 - s0, e2 = s2 - s0;
  float area = e1.x * e2.y - e1.y * e2.x;
  if (abs(area) < 1e-9) return;  // seen edge on: covers no sample
  // Window depth is affine in window coordinates: solve for its gradient.
  float z0 = windowDepth(c0);
  float dz1 = windowDepth(c1) - z0, dz2 = windowDepth(c2) - z0;
  vec2 gradient = vec2(dz1 * e2.y - dz2 * e1.y, dz2 * e1.x - dz1 * e2.x) / area;
  vec2 lo = clamp(floor(min(s0, min(s1, s2))) - 1.0, vec2(0.0), vec2(u_size));
  vec2 hi = clamp(ceil(max(s0, max(s1, s2))) + 1.0, vec2(0.0), vec2(u_size));
  if (any(greaterThanEqual(lo, hi))) return;
  // Counter-clockwise; each edge's line n·p = c with n outward, pushed out by the pixel's
  // half-extent along n; corner i where the pushed edges i−1 and i meet.
  vec2 s[3] = area > 0.0 ? vec2[](s0, s1, s2) : vec2[](s0, s2, s1);
  vec3 lines[3];
  for (int i = 0; i < 3; ++i) {
    vec2 e = s[(i + 1) % 3] - s[i];
    vec2 n = normalize(vec2(e.y, -e.x));
    lines[i] = vec3(n, dot(n, s[i]) + 0.5 * (abs(n.x) + abs(n.y)) + 1e-3);
  }
  vec2 grown[3];
  for (int i = 0; i < 3; ++i) {
    vec3 a = lines[(i + 2) % 3], b = lines[i];
    float det = a.x * b.y - a.y * b.x;
    grown[i] = vec2(a.z * b.y - a.y * b.z, a.x * b.z - a.z * b.x) / det;
  }
  // The grown triangle clipped to the box: a convex polygon of up to 9 corners, drawn as a fan.
  vec2 polygon[9];
  int n = 3;
  for (int i = 0; i < 3; ++i) polygon[i] = grown[i];
  for (int side = 0; side < 4; ++side) {
    vec2 next[9];
    int m = 0;
    for (int i = 0; i < n; ++i) {
      vec2 a = polygon[i], b = polygon[(i + 1) % n];
      float da = side == 0 ? a.x - lo.x : side == 1 ? hi.x - a.x : side == 2 ? a.y - lo.y : hi.y - a.y;
      float db = side == 0 ? b.x - lo.x : side == 1 ? hi.x - b.x : side == 2 ? b.y - lo.y : hi.y - b.y;
      if (da >= 0.0) next[m++] = a;
      if ((da >= 0.0) != (db >= 0.0) && m < 9) next[m++] = mix(a, b, da / (da - db));
    }
    n = m;
    for (int i = 0; i < n; ++i) polygon[i] = next[i];
    if (n < 3) return;
  }
  // A triangle strip that walks the fan: 0, 1, n−1, 2, n−2, ...
  for (int k = 0; k < n; ++k) {
    int i = (k % 2 == 0) ? (n - k / 2) % n : (k + 1) / 2;
    gl_Layer = g_layer[0];
    v_a = s0;
    v_b = s1;
    v_c = s2;
    v_depth_plane = vec3(gradient, z0);
    v_point = g_point[0];
    gl_Position = vec4(polygon[i] / float(u_size) * 2.0 - 1.0, 0.0, 1.0);
    EmitVertex();
  }
  EndPrimitive();
}

void main() {
  // Sutherland–Hodgman against the near plane z > −w.
  vec4 clipped[4];
  int n = 0;
  for (int i = 0; i < 3; ++i) {
    vec4 a = gl_in[i].gl_Position, b = gl_in[(i + 1) % 3].gl_Position;
    float da = a.z + a.w, db = b.z + b.w;
    if (a.w == 0.0 && b.w == 0.0) return;  // the vertex shader's "draw nothing"
    if (da > 0.0) clipped[n++] = a;
    if ((da > 0.0) != (db > 0.0)) clipped[n++] = mix(a, b, da / (da - db));
  }
  if (n < 3) return;
  emitTriangle(clipped[0], clipped[1], clipped[2]);
  if (n == 4) emitTriangle(clipped[0], clipped[2], clipped[3]);
}
