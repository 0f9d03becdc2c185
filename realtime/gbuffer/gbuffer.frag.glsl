#include "realtime/gpu_scene/scene.glsl"
#include "realtime/gpu_scene/shading_normal.glsl"

in vec3 world_position;
flat in vec3 world_normal;
in vec3 world_shading_normal;
flat in uint material;

layout(location = 0) out vec4 out_position;  // world position, w: distance along the ray
layout(location = 1) out vec4 out_normal;    // shading normal, front side; w: material
layout(location = 2) out vec4 out_albedo;    // diffuse reflectance, w: 1

#ifdef EXPLICIT_VIEW
flat in vec3 view_eye;
#endif

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
  // The perspective-correct interpolation of a planar triangle's positions is the point the
  // pixel's ray hits, so its distance from the eye is the path tracer's t.
  out_position = vec4(world_position, length(world_position - eye));
  out_normal = vec4(normal, float(material));
  out_albedo = vec4(materialDiffuse(material), 1.0);
}
