// Whether the current context offers an OpenGL extension (for optional fast paths that have a
// core fallback, such as layer selection in the vertex shader).
#pragma once

#include <string_view>

namespace gib::rt::gl {

bool hasExtension(std::string_view name);

}  // namespace gib::rt::gl
