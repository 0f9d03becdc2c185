// The fixed-function state a pass draws with (depth test, blending, culling, write masks, polygon
// offset, clip distances, point size, logic op, scissor, viewport) as one value, applied for the
// length of a scope. Outside every scope the GL holds the default state, PipelineState{}: what GL
// gives a new context (no depth test but depth writes on, no blending, no culling, every colour
// channel written, nothing else enabled). A pass states what it needs and assumes nothing else,
// and no pass leaks state into the next: a scope's end puts back the state it found.
//
// A scope issues only the calls for what differs from the state it knows to be in place, so
// nothing else may change that state behind its back: only realtime/gl/ turns it on and off or
// sets its functions with raw GL calls (a test checks the rest of realtime/). RenderTarget's bind
// sets its viewport, which scopes put back as they found it, and its clear the write masks to the
// default's values. context.cpp turns on debug output once, when the context is made, which is no
// pass's business.
#pragma once

#include "realtime/gl/gl.h"

#include <array>
#include <optional>

namespace gib::rt::gl {

// A rectangle of the framebuffer in pixels, from its lower left corner (viewport, scissor box).
struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
  bool operator==(const PixelRect&) const = default;
};

// glBlendFuncSeparate's factors: colour = src_rgb·source + dst_rgb·destination, alpha likewise.
struct BlendFactors {
  GLenum src_rgb, dst_rgb, src_alpha, dst_alpha;
  bool operator==(const BlendFactors&) const = default;
};
// The source added to what the target holds: the passes that sum light.
inline constexpr BlendFactors kAdditiveBlend = {GL_ONE, GL_ONE, GL_ONE, GL_ONE};

// glPolygonOffset's slope factor and constant units, for filled polygons.
struct PolygonOffset {
  float factor, units;
  bool operator==(const PolygonOffset&) const = default;
};

struct PipelineState {
  // The depth comparison (GL_LESS, GL_LEQUAL, GL_ALWAYS); none: no depth test, and so no depth
  // written by draws.
  std::optional<GLenum> depth_test = std::nullopt;
  // Whether depth is written where the test passes; also whether a clear clears depth.
  bool depth_write = true;
  // None: the source replaces the target.
  std::optional<BlendFactors> blend = std::nullopt;
  // GL_BACK or GL_FRONT; none: both sides drawn.
  std::optional<GLenum> cull_face = std::nullopt;
  // Red, green, blue, alpha written into every draw buffer; also what a clear clears.
  std::array<bool, 4> color_write = {true, true, true, true};
  // Of filled polygons' depth.
  std::optional<PolygonOffset> polygon_offset = std::nullopt;
  // gl_ClipDistance[0 .. n − 1] clip.
  int clip_distances = 0;
  // Points take gl_PointSize.
  bool program_point_size = false;
  // A colour logic op (GL_OR, ...) instead of blending.
  std::optional<GLenum> logic_op = std::nullopt;
  std::optional<PixelRect> scissor = std::nullopt;
  // Every viewport of the array; none: the one in place (RenderTarget::bind sets its own). The
  // scope's end puts back the viewport it found.
  std::optional<PixelRect> viewport = std::nullopt;

  bool operator==(const PipelineState&) const = default;
};

// Applies a state from construction to destruction, then puts back the enclosing scope's, or the
// default state outside every scope. Scopes nest (the inner one's state replaces the outer one's
// whole, not field by field) and end in reverse order, as objects on the stack do; one thread's
// scopes are independent of another's, as its current GL context is. Only the calls for what
// differs from the state in place are issued.
class PipelineScope {
 public:
  explicit PipelineScope(const PipelineState& state);
  ~PipelineScope();
  PipelineScope(const PipelineScope&) = delete;
  PipelineScope& operator=(const PipelineScope&) = delete;

 private:
  PipelineState state_;
  const PipelineScope* enclosing_;
  std::array<GLint, 4> found_viewport_{};  // when state_ sets one
};

}  // namespace gib::rt::gl
