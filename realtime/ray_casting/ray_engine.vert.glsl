// §5.2: one full-target triangle per scene triangle (instance = the triangle's list index), so
// every ray's pixel meets every triangle.
flat out int v_slot;

void main() {
  vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
  v_slot = gl_InstanceID;
}
