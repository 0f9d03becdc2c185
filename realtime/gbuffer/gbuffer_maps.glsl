// The G-buffer maps deferred passes read (GBuffer::bindTextures) at their units of the binding
// plan, texel for texel.
#include "realtime/gl/binding_plan_shared.h"

layout(binding = kGBufferPositionUnit) uniform sampler2D u_gbuffer_position;  // xyz world, w ray distance (−1: none)
layout(binding = kGBufferNormalUnit) uniform sampler2D u_gbuffer_normal;  // xyz shading normal, w material
