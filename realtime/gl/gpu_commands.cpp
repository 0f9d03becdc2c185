#include "realtime/gl/gpu_commands.h"

namespace gib::rt::gl {

namespace {
// Per thread: a GL context is current on one thread, and so is its profiler.
thread_local std::uint64_t commands_issued = 0;
}  // namespace

void drawArrays(GLenum mode, GLint first, GLsizei count) {
  ++commands_issued;
  glDrawArrays(mode, first, count);
}

void drawArraysInstanced(GLenum mode, GLint first, GLsizei count, GLsizei instances) {
  ++commands_issued;
  glDrawArraysInstanced(mode, first, count, instances);
}

void multiDrawArraysIndirect(GLenum mode, std::size_t offset, GLsizei records) {
  ++commands_issued;
  glMultiDrawArraysIndirect(mode, reinterpret_cast<const void*>(offset), records, 0);
}

void dispatchCompute(GLuint x, GLuint y, GLuint z) {
  ++commands_issued;
  glDispatchCompute(x, y, z);
}

std::uint64_t gpuCommandsIssued() {
  return commands_issued;
}

}  // namespace gib::rt::gl
