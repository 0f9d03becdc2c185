// The GL commands that make the GPU work (draws and compute dispatches), issued through these
// wrappers so that the pass profiler can count them per pass: a frame made of a hundred tiny
// draws is bound by per-command overhead on a real GPU, which the per-pass times of a software
// renderer do not show (issue "fewer passes": draws per frame on the job pages). Every draw and
// dispatch in the realtime layer goes through here; a test checks that none bypasses it.
#pragma once

#include "realtime/gl/gl.h"

#include <cstddef>
#include <cstdint>

namespace gib::rt::gl {

void drawArrays(GLenum mode, GLint first, GLsizei count);
void drawArraysInstanced(GLenum mode, GLint first, GLsizei count, GLsizei instances);
// The records of the bound GL_DRAW_INDIRECT_BUFFER from byte `offset` (DrawArraysIndirectCommand,
// tightly packed): one command however many records, as the GPU's front end walks them itself.
void multiDrawArraysIndirect(GLenum mode, std::size_t offset, GLsizei records);
void dispatchCompute(GLuint x, GLuint y, GLuint z);

// Draws and dispatches issued so far on this thread (each call counts one, however many
// instances or work groups it has).
std::uint64_t gpuCommandsIssued();

}  // namespace gib::rt::gl
