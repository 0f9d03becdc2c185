// First-bounce injection for scenes lit by spot and directional lights (the chamber): their
// direct light, reflected by every atlas texel, computed once with `direct`'s shadow maps and
// added into the source map, which shooting treats as emission
// (realtime/atlas/atlas_light.frag.glsl). Area lights need none: their emissive triangles are atlas
// texels with emission, the paper's setting. The sky is not injected (the technique leaves it out;
// `gibench list techniques` says so).
#pragma once

#include "realtime/atlas/atlas_textures.h"
#include "realtime/gpu_scene/gpu_scene.h"

namespace gib::rt {

// Adds the direct light into the colour attachment 0 of `source` (resolution² texels); returns
// the number of light samples injected.
int injectDirectLight(const GpuScene& scene, const atlas::AtlasTextures& atlas,
                      const gl::Framebuffer& source);

}  // namespace gib::rt
