#include "support/gl_memory.h"

namespace gib::test {

std::int64_t allocatedTextureBytes(const rt::gl::Texture& texture) {
  const auto level0 = [&](GLenum parameter) {
    GLint value = 0;
    glGetTextureLevelParameteriv(texture.id(), 0, parameter, &value);
    return std::int64_t(value);
  };
  std::int64_t bits = 0;
  for (GLenum component : {GL_TEXTURE_RED_SIZE, GL_TEXTURE_GREEN_SIZE, GL_TEXTURE_BLUE_SIZE,
                           GL_TEXTURE_ALPHA_SIZE, GL_TEXTURE_DEPTH_SIZE, GL_TEXTURE_STENCIL_SIZE})
    bits += level0(component);
  return level0(GL_TEXTURE_WIDTH) * level0(GL_TEXTURE_HEIGHT) * level0(GL_TEXTURE_DEPTH) * bits / 8;
}

}  // namespace gib::test
