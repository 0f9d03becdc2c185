// The GLSL files of the realtime layer, compiled into the program (cmake/EmbedGlsl.cmake).
#pragma once

#include <span>
#include <string_view>

namespace gib::rt::gl {

struct EmbeddedFile {
  std::string_view path;  // relative to realtime/, e.g. "techniques/direct/shade.frag.glsl"
  std::string_view text;
};

std::span<const EmbeddedFile> embeddedGlslFiles();

}  // namespace gib::rt::gl
