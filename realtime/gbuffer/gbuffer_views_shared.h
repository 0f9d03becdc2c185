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
  // Triangles [x, y) of the scene's list are not drawn into this view (a distance map leaves
  // out the object it belongs to, book §6.1); x == y: every triangle is.
  ivec4 excluded_triangles;
};

// Views per draw: the viewports every GL 4.5 implementation offers (GL_MAX_VIEWPORTS ≥ 16).
const int kMaxGBufferViewsPerDraw = 16;

#ifdef __cplusplus
static_assert(sizeof(GBufferViewRecord) == 96, "std140: a mat4 and two vec4s");
}  // namespace gib::rt::gpu
#endif
