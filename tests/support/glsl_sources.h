// In-memory GLSL files for tests, as a lookup for expandIncludes and buildProgram: a test shader
// (a broken one above all) cannot live under realtime/, where it would be embedded in the product.
#pragma once

#include "realtime/gl/shader_library.h"

#include <map>
#include <string>

namespace gib::test {

// Paths relative to realtime/, as for the embedded files; an unknown path is a ShaderError.
rt::gl::GlslLookup glslSources(std::map<std::string, std::string, std::less<>> files);

}  // namespace gib::test
