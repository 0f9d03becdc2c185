// The atlas maps of realtime/atlas/atlas_textures.h (units 8..11, clear of the units techniques
// use for their own maps), texel for texel.
layout(binding = 8) uniform sampler2D u_atlas_position;   // xyz sample point, w 1 inside a chart
layout(binding = 9) uniform sampler2D u_atlas_normal;     // xyz unit normal, w world area
layout(binding = 10) uniform sampler2D u_atlas_albedo;    // rgb ρ
layout(binding = 11) uniform sampler2D u_atlas_emission;  // rgb emitted radiance, front side
