#include "realtime/gpu_scene/scene.glsl"
#include "realtime/gpu_scene/shading_normal.glsl"

in vec3 world_position;
flat in vec3 world_normal;
in vec3 world_shading_normal;
flat in uint material;

layout(location = 0) out vec4 out_position;  // world position, w: distance along the ray
layout(location = 1) out vec4 out_normal;    // shading normal, front side; w: material
// Diffuse reflectance; w: ±(t + 1) for scene triangle t, + on its front side (GBuffer::albedo).
layout(location = 2) out vec4 out_albedo;

#ifdef EXPLICIT_VIEW
flat in vec3 view_eye;
#endif
flat in int scene_triangle;

void main() {
  // The geometric normal on a flat mesh, the interpolated one on a smooth mesh.
  vec3 normal = shadingNormal(world_shading_normal, world_normal);
#ifdef EXPLICIT_VIEW
  vec3 eye = view_eye;
  // Turned towards the eye: a probe's view is shaded for the light it reflects, never for
  // emission, and the shading pass knows no other eye than the camera's. The geometric normal
  // decides the side, which an interpolated normal may get wrong near a silhouette.
  if (dot(world_normal, eye - world_position) < 0.0) normal = -normal;
#else
  vec3 eye = camera.position.xyz;
  // Not turned towards the camera: reflection is two-sided, but emission is not.
#endif
  bool front = dot(world_normal, eye - world_position) >= 0.0;
  // The perspective-correct interpolation of a planar triangle's positions is the point the
  // pixel's ray hits, so its distance from the eye is the path tracer's t.
  out_position = vec4(world_position, length(world_position - eye));
  out_normal = vec4(normal, float(material));
  // Which triangle, and which side of it (exact in a float up to 2²⁴ triangles): a distance
  // map's texel needs its object and whether an emitter faces the map's centre, which a probe
  // view's turned normal no longer tells; the specular pass needs the object of a pixel.
  float triangle_code = float(scene_triangle + 1);
  out_albedo = vec4(materialDiffuse(material), front ? triangle_code : -triangle_code);
}
