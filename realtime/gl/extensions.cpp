#include "realtime/gl/extensions.h"

#include "realtime/gl/gl.h"

namespace gib::rt::gl {

bool hasExtension(std::string_view name) {
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i) {
    const auto* extension = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
    if (extension && name == extension) return true;
  }
  return false;
}

}  // namespace gib::rt::gl
