// The camera's view of the indirect atlas, bilinear between exit points (the book: "rendered in a
// standard way with linear interpolation between the exit points"). The atlas holds the front
// side of each surface, so a back face shows nothing. u_show_albedo draws the diffuse
// reflectance instead, dimmed: the backdrop of the entry-point figure.
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/atlas/atlas_maps.glsl"
#include "realtime/techniques/light_path_map/light_path_map_shared.h"

layout(binding = kIndirectUnit) uniform sampler2D u_indirect;
uniform bool u_show_albedo;
in vec2 v_atlas_uv;
in vec3 v_world;
flat in vec3 v_normal;
layout(location = 0) out vec4 o_radiance;

void main() {
  bool front = dot(v_normal, camera.position.xyz - v_world) > 0.0;
  vec3 radiance = u_show_albedo ? 0.5 * texture(u_atlas_albedo, v_atlas_uv).rgb
                                : texture(u_indirect, v_atlas_uv).rgb;
  o_radiance = vec4(front ? radiance : vec3(0.0), 1.0);
}
