// Programs from the embedded GLSL files. A file names its dependencies with
// `#include "path"` (relative to realtime/), expanded here with `#line` directives so that a
// compile error reports the file and line it comes from. Files carry no #version: every stage is
// compiled as `#version 450 core` followed by the caller's defines.
#pragma once

#include "realtime/gl/embedded_glsl.h"
#include "realtime/gl/objects.h"

#include <stdexcept>

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace gib::rt::gl {

// A compile or link error; the message names the file and line of each error.
class ShaderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ShaderStage {
  GLenum type;       // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_GEOMETRY_SHADER, GL_COMPUTE_SHADER
  std::string path;  // embedded file, relative to realtime/
};

// The text of an embedded file; throws ShaderError if there is none of that path.
std::string_view glslFile(std::string_view path);

// Source after #include expansion, and the file each source-string number stands for.
struct ExpandedSource {
  std::string text;
  std::vector<std::string> files;  // index = GLSL source-string number used in #line
};
// `lookup` returns a file's text (the embedded files by default; tests pass their own).
ExpandedSource expandIncludes(std::string_view path, std::string_view defines,
                              std::string_view (*lookup)(std::string_view) = glslFile);

// Rewrites a driver's info log ("0:12(3): error: ..." from Mesa, "0(12) : error ..." from
// NVIDIA) so that each location reads "path:line".
std::string translateInfoLog(std::string_view log, const std::vector<std::string>& files);

// Compiles and links the stages; `defines` is inserted after #version ("#define N 4\n...").
Program buildProgram(std::initializer_list<ShaderStage> stages, std::string_view defines = "");

}  // namespace gib::rt::gl
