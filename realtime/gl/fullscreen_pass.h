// A pass that runs a fragment shader once per pixel of the bound framebuffer: one triangle that
// covers the viewport, its corners made from gl_VertexID (fullscreen.vert.glsl), so there is no
// vertex buffer, only the empty vertex array a core-profile draw needs. Deferred shading, the
// atlas passes in texture space and the irradiance volume's indirect light all draw this way.
#pragma once

#include "realtime/gl/objects.h"

#include <string_view>

namespace gib::rt::gl {

class FullScreenPass {
 public:
  FullScreenPass() = default;
  // The program of fullscreen.vert.glsl and `fragment_path` (an embedded file), with `defines`.
  explicit FullScreenPass(std::string_view fragment_path, std::string_view defines = "");

  const Program& program() const { return program_; }
  // Makes the program current, for setting uniforms before draw().
  void use() const { program_.use(); }
  // Draws the triangle with the program into the bound framebuffer and viewport; the caller has
  // set depth test and blending as the pass needs them.
  void draw() const;

 private:
  Program program_;
  VertexArray empty_vertex_array_;
};

}  // namespace gib::rt::gl
