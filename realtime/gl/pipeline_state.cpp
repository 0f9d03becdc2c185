#include "realtime/gl/pipeline_state.h"

#include <algorithm>

namespace gib::rt::gl {

namespace {

// The innermost scope of this thread; none: the GL holds the default state.
thread_local const PipelineScope* innermost = nullptr;

void enable(GLenum capability, bool on) {
  if (on)
    glEnable(capability);
  else
    glDisable(capability);
}

// The GL calls that take the GL from state `from` (the state in place) to `to`. Parameters of a
// disabled feature (blend factors while blending is off, ...) may be left stale in the GL: they
// are set whenever the feature is turned on.
void change(const PipelineState& from, const PipelineState& to) {
  if (to.depth_test != from.depth_test) {
    if (to.depth_test.has_value() != from.depth_test.has_value())
      enable(GL_DEPTH_TEST, to.depth_test.has_value());
    if (to.depth_test) glDepthFunc(*to.depth_test);
  }
  if (to.depth_write != from.depth_write) glDepthMask(to.depth_write ? GL_TRUE : GL_FALSE);
  if (to.blend != from.blend) {
    if (to.blend.has_value() != from.blend.has_value()) enable(GL_BLEND, to.blend.has_value());
    if (to.blend)
      glBlendFuncSeparate(to.blend->src_rgb, to.blend->dst_rgb, to.blend->src_alpha,
                          to.blend->dst_alpha);
  }
  if (to.cull_face != from.cull_face) {
    if (to.cull_face.has_value() != from.cull_face.has_value())
      enable(GL_CULL_FACE, to.cull_face.has_value());
    if (to.cull_face) glCullFace(*to.cull_face);
  }
  if (to.color_write != from.color_write) {
    const auto& c = to.color_write;
    glColorMask(c[0] ? GL_TRUE : GL_FALSE, c[1] ? GL_TRUE : GL_FALSE, c[2] ? GL_TRUE : GL_FALSE,
                c[3] ? GL_TRUE : GL_FALSE);
  }
  if (to.polygon_offset != from.polygon_offset) {
    if (to.polygon_offset.has_value() != from.polygon_offset.has_value())
      enable(GL_POLYGON_OFFSET_FILL, to.polygon_offset.has_value());
    if (to.polygon_offset) glPolygonOffset(to.polygon_offset->factor, to.polygon_offset->units);
  }
  for (int i = 0; i < std::max(from.clip_distances, to.clip_distances); ++i)
    if ((i < to.clip_distances) != (i < from.clip_distances))
      enable(GLenum(GL_CLIP_DISTANCE0 + i), i < to.clip_distances);
  if (to.program_point_size != from.program_point_size)
    enable(GL_PROGRAM_POINT_SIZE, to.program_point_size);
  if (to.logic_op != from.logic_op) {
    if (to.logic_op.has_value() != from.logic_op.has_value())
      enable(GL_COLOR_LOGIC_OP, to.logic_op.has_value());
    if (to.logic_op) glLogicOp(*to.logic_op);
  }
  if (to.scissor != from.scissor) {
    if (to.scissor.has_value() != from.scissor.has_value())
      enable(GL_SCISSOR_TEST, to.scissor.has_value());
    if (to.scissor) glScissor(to.scissor->x, to.scissor->y, to.scissor->width, to.scissor->height);
  }
}

}  // namespace

PipelineScope::PipelineScope(const PipelineState& state) : state_(state), enclosing_(innermost) {
  change(enclosing_ ? enclosing_->state_ : PipelineState{}, state_);
  if (state_.viewport) {
    glGetIntegerv(GL_VIEWPORT, found_viewport_.data());
    const PixelRect& v = *state_.viewport;
    glViewport(v.x, v.y, v.width, v.height);
  }
  innermost = this;
}

PipelineScope::~PipelineScope() {
  change(state_, enclosing_ ? enclosing_->state_ : PipelineState{});
  if (state_.viewport)
    glViewport(found_viewport_[0], found_viewport_[1], found_viewport_[2], found_viewport_[3]);
  innermost = enclosing_;
}

}  // namespace gib::rt::gl
