// The atlas maps of realtime/atlas/atlas_textures.h at their units of the binding plan, texel for
// texel.
#include "realtime/gl/binding_plan_shared.h"

layout(binding = kAtlasPositionUnit) uniform sampler2D u_atlas_position;  // xyz sample point, w 1 inside a chart
layout(binding = kAtlasNormalUnit) uniform sampler2D u_atlas_normal;      // xyz unit normal, w world area
layout(binding = kAtlasAlbedoUnit) uniform sampler2D u_atlas_albedo;      // rgb ρ
layout(binding = kAtlasEmissionUnit) uniform sampler2D u_atlas_emission;  // rgb emitted radiance, front side
