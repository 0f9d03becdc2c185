// Faults injected into the GL runtime for testing what a user sees when a driver fails
// (docs/reliability.md, "Faults"): the environment variable GIB_GL_FAULT names them, a
// comma-separated list of
//   shader-compile          every shader compiles with an error
//   texture-out-of-memory   every texture allocation reports GL_OUT_OF_MEMORY
//   context                 no GL context can be created
// Unset or empty: no fault. The hooks sit where a real failure is detected, so the injected fault
// takes the real failure's path from there on.
#pragma once

namespace gib::rt::gl {

enum class GlFault { kShaderCompile, kTextureOutOfMemory, kContext };

// Whether GIB_GL_FAULT names `fault`. Read on every call (the hooks are at compile, allocation and
// context creation, never inside a frame), so a test can set it case by case. A value that names
// no fault is a gib::InputError.
bool glFaultInjected(GlFault fault);

}  // namespace gib::rt::gl
