// Programs from the embedded GLSL files. A file names its dependencies with
// `#include "path"` (relative to realtime/), expanded here with a map from each line of the
// expanded text back to its file and line, so that a compile error reports where it comes from.
// Files carry no #version: every stage is compiled as `#version 450 core` followed by the
// caller's defines.
#pragma once

#include "realtime/gl/embedded_glsl.h"
#include "realtime/gl/objects.h"

#include <stdexcept>

#include <functional>
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

// Where sources come from: a path relative to realtime/ → its text (throwing ShaderError when
// there is none). glslFile by default; tests pass in-memory sources, since a .glsl file under
// realtime/ would be embedded in the product.
using GlslLookup = std::function<std::string_view(std::string_view)>;

// Where one line of an expanded source comes from.
struct SourceLine {
  int file;  // index into ExpandedSource::files; kDefinesFile for #version and the defines
  int line;  // 1-based in that file (in the defines string; 0 for the #version line)
  static constexpr int kDefinesFile = -1;
  bool operator==(const SourceLine&) const = default;
};

// Source after #include expansion. It has no #line directives: Mesa drops their source-string
// number from most error locations (its parser's YYLLOC_DEFAULT resets it to 0), so a file
// number would be lost; the line number of the one expanded string is kept by every driver and
// is looked up in `lines` instead.
struct ExpandedSource {
  std::string text;
  std::vector<std::string> files;  // the stage's own file first, then each include once
  std::vector<SourceLine> lines;   // one per line of `text`: lines[n − 1] is line n
};
ExpandedSource expandIncludes(std::string_view path, std::string_view defines,
                              const GlslLookup& lookup = glslFile);

// Rewrites a driver's info log ("0:12(3): error: ..." from Mesa, "0(12) : error ..." from
// NVIDIA, 12 being a line of the expanded text) so that each location reads
// "realtime/<file>:<line>", or "defines:<line>" for an error in the defines.
std::string translateInfoLog(std::string_view log, const ExpandedSource& source);

// Compiles and links the stages; `defines` is inserted after #version ("#define N 4\n...").
Program buildProgram(std::initializer_list<ShaderStage> stages, std::string_view defines = "",
                     const GlslLookup& lookup = glslFile);

}  // namespace gib::rt::gl
