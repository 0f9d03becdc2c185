// A text file compiled into the program (cmake/EmbedFiles.cmake): the realtime layer's GLSL and
// shared headers, the report's stylesheet and script. Keyed by the path relative to the project
// root, so a message can name the file a user finds in the repository.
#pragma once

#include <span>
#include <string_view>

namespace gib {

struct EmbeddedFile {
  std::string_view path;  // e.g. "realtime/lighting/shade_light.frag.glsl"
  std::string_view text;
};

// The file of `path` among `files`, or nullptr.
inline const EmbeddedFile* findEmbeddedFile(std::span<const EmbeddedFile> files,
                                            std::string_view path) {
  for (const EmbeddedFile& file : files)
    if (file.path == path) return &file;
  return nullptr;
}

}  // namespace gib
