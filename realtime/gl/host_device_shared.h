// The dialect of the headers that C++ and GLSL both read (`*_shared.h`; docs/architecture.md,
// "Declared GPU layouts"): binding points, sizes, buffer structs and small functions written once,
// in the subset the two languages share: `const int` and `const float` constants, structs of
// GLSL vector and matrix types, and functions marked GIB_SHARED_FUNCTION.
//
// A shared header starts with `#pragma once`, includes this file, and puts its C++-only lines (the
// namespace gib::rt::gpu, includes, static_asserts) inside `#ifdef __cplusplus` blocks, which
// gl::expandIncludes drops. Every name lands in one C++ namespace, as it lands in GLSL's one global
// scope, so a clash between two shared headers is a C++ compile error before it is a shader one.
#pragma once

#ifdef __cplusplus
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>

namespace gib::rt::gpu {
using glm::ivec2;
using glm::ivec3;
using glm::ivec4;
using glm::mat4;
using glm::vec2;
using glm::vec3;
using glm::vec4;
using uint = std::uint32_t;
}  // namespace gib::rt::gpu

#define GIB_SHARED_FUNCTION inline
#else
#define GIB_SHARED_FUNCTION
#endif
