// The shooter's visibility map (Barsi & Jakab §3.2, book §7.1.2): the distance of the nearest
// surface in every direction of the hemisphere above the shooter, as
//   HEMICUBE: five faces of a hemicube (the book's choice): a full top face along the normal and
//             four half side faces, layers 0..4 of an array, each u_map_size² (the side faces use
//             the lower half of their layer's rows), or
//   otherwise the hemispherical projection (the paper's choice): a direction ω maps to (ωx, ωy)
//             on the unit disk, one layer. Triangles are rasterised with straight edges between
//             projected vertices, which is exact only when they are small (the paper's
//             tessellation caveat, measured by the `tessellation` parameter).
// Shared by the pass that writes the map and the update pass that looks receivers up in it.
uniform int u_map_size;  // texels per side of a face (of the disk's square)

#ifdef HEMICUBE
// Face f's (screen x, screen y, depth) of a point l in the shooter frame, so that screen/depth is
// the face's NDC. Side faces map the normal's half-space [0, 1] of up/depth onto NDC y [−1, 1].
vec3 hemicubeFaceCoordinates(vec3 l, int face) {
  if (face == 0) return vec3(l.x, l.y, l.z);
  vec3 s;  // (across, up, depth)
  if (face == 1) s = vec3(l.y, l.z, l.x);
  else if (face == 2) s = vec3(-l.y, l.z, -l.x);
  else if (face == 3) s = vec3(-l.x, l.z, l.y);
  else s = vec3(l.x, l.z, -l.y);
  return vec3(s.x, 2.0 * s.y - s.z, s.z);
}

// The face a direction above the shooter (l.z > 0) falls on.
int hemicubeFace(vec3 l) {
  vec3 a = abs(l);
  if (l.z >= a.x && l.z >= a.y) return 0;
  if (a.x >= a.y) return l.x > 0.0 ? 1 : 2;
  return l.y > 0.0 ? 3 : 4;
}

// Rows a face uses: the top face all, a side face half.
int hemicubeFaceRows(int face) {
  return face == 0 ? u_map_size : u_map_size / 2;
}
#else
vec2 hemisphereCoordinates(vec3 l) {
  return l.xy / length(l);
}
#endif
