// The normal a fragment shades with, from the vertex normals of gpu_scene_shared.h: on a mesh
// with shading normals, their interpolation (kVertexShadingNormalLocation) renormalised; on a
// flat mesh, whose shading normals are zero (and stay exactly zero through any interpolation),
// the triangle's geometric normal `geometric`, bit for bit. Both on the front side: a pass that
// turns the normal towards a viewer decides the side with the geometric normal and turns this one.
vec3 shadingNormal(vec3 interpolated, vec3 geometric) {
  return interpolated == vec3(0.0) ? geometric : normalize(interpolated);
}
