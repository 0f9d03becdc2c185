// A linked program and its uniforms, set by name through typed setters. The GL ignores a uniform
// location of −1 without a word, which glGetUniformLocation returns for a mistyped name as for a
// uniform the compiler dropped; here both are errors naming the program and the uniform, and a
// value of the wrong GLSL type is one too. A uniform that some variant of a program does not read
// (its defines leave the code that reads it out, and the linker drops it) is set through
// setIfPresent, with a comment at the call saying which variant.
#pragma once

#include "realtime/gl/gl.h"
#include "realtime/gl/unique_name.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <functional>
#include <initializer_list>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace gib::rt::gl {

// See shader_library.h for how programs are built from the embedded GLSL.
class Program {
 public:
  Program() = default;
  // Takes a linked program; `label` names it in errors (buildProgram: its stages' files).
  Program(GLuint name, std::string label) : name_(name), label_(std::move(label)) {}

  GLuint id() const { return name_.get(); }
  const std::string& label() const { return label_; }
  void use() const { glUseProgram(id()); }

  // Whether the linked program has an active uniform of this name (outside uniform blocks).
  bool hasUniform(std::string_view name) const;
  // Its location; throws std::logic_error naming the program and the uniform when there is none.
  GLint uniform(std::string_view name) const;

  // Sets an active uniform (glProgramUniform*: the program need not be current). Throws
  // std::logic_error when the program has none of that name, or one of another GLSL type (int
  // also sets a bool, as glUniform1i does).
  void set(std::string_view name, int value) const;
  void set(std::string_view name, unsigned value) const;
  void set(std::string_view name, float value) const;
  void set(std::string_view name, const glm::ivec2& value) const;
  void set(std::string_view name, const glm::vec3& value) const;
  void set(std::string_view name, const glm::vec4& value) const;
  void set(std::string_view name, const glm::mat4& value) const;
  // The first values.size() elements of a vec3 array.
  void set(std::string_view name, std::span<const glm::vec3> values) const;

  // Sets the uniform when this variant of the program reads it, and does nothing when the linker
  // dropped it; the caller says in a comment which variants leave it out.
  template <typename T>
  void setIfPresent(std::string_view name, const T& value) const {
    if (hasUniform(name)) set(name, value);
  }

 private:
  struct ActiveUniform {
    GLint location;
    GLenum type;
    GLint elements;  // 1, or an array's active length
  };
  // The active uniform `name`, of one of the `types`; throws std::logic_error otherwise.
  const ActiveUniform& active(std::string_view name, std::initializer_list<GLenum> types) const;
  const std::map<std::string, ActiveUniform, std::less<>>& activeUniforms() const;

  UniqueName<detail::deleteProgram> name_;
  std::string label_;
  // Read from the driver at the first look-up (the program is linked by then).
  mutable std::optional<std::map<std::string, ActiveUniform, std::less<>>> uniforms_;
};

}  // namespace gib::rt::gl
