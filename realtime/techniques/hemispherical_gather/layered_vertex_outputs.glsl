// What the vertex shaders of gather views, voxel slices and the slices' pass hand to
// gather_view.geom.glsl: the atlas coordinate, world position and normal for the fragment
// shader, the layer to draw into, and the clip distances (the horizon, the near box).
#include "realtime/techniques/hemispherical_gather/hemispherical_gather_shared.h"

out vec2 g_atlas_uv;
out vec3 g_world;
flat out vec3 g_normal;
flat out int g_layer;
out gl_PerVertex {
  vec4 gl_Position;
  float gl_ClipDistance[kGatherClipDistances];
};
