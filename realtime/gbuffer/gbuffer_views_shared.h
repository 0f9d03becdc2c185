// The views of GBuffer::renderViews as its vertex shader reads them (a uniform block, std140):
// one multi-draw rasterises the scene into up to kMaxGBufferViewsPerDraw rectangles of the
// G-buffer (the irradiance volume's probe cube faces), records with base instance i through view i
// into viewport i of the viewport array, instead of one draw per view.
#pragma once
#include "realtime/gl/host_device_shared.h"

#ifdef __cplusplus
namespace gib::rt::gpu {
#endif

struct GBufferViewRecord {
  mat4 view_projection;  // world to the view's clip space
  vec4 eye;              // xyz the view's eye
};

// Views per draw: the viewports every GL 4.5 implementation offers (GL_MAX_VIEWPORTS ≥ 16).
const int kMaxGBufferViewsPerDraw = 16;

#ifdef __cplusplus
static_assert(sizeof(GBufferViewRecord) == 80, "std140: a mat4 and a vec4");
}  // namespace gib::rt::gpu
#endif
