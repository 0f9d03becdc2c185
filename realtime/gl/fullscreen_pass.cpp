#include "realtime/gl/fullscreen_pass.h"

#include "realtime/gl/gpu_commands.h"
#include "realtime/gl/shader_library.h"

#include <string>

namespace gib::rt::gl {

FullScreenPass::FullScreenPass(std::string_view fragment_path, std::string_view defines)
    : program_(buildProgram({{GL_VERTEX_SHADER, "realtime/gl/fullscreen.vert.glsl"},
                             {GL_FRAGMENT_SHADER, std::string(fragment_path)}},
                            defines)) {}

void FullScreenPass::draw() const {
  program_.use();
  empty_vertex_array_.bind();
  gl::drawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace gib::rt::gl
