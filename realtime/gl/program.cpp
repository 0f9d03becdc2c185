#include "realtime/gl/program.h"

#include <fmt/format.h>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <stdexcept>

namespace gib::rt::gl {

namespace {

std::string glslTypeName(GLenum type) {
  switch (type) {
    case GL_BOOL:
      return "bool";
    case GL_INT:
      return "int";
    case GL_UNSIGNED_INT:
      return "uint";
    case GL_FLOAT:
      return "float";
    case GL_INT_VEC2:
      return "ivec2";
    case GL_FLOAT_VEC3:
      return "vec3";
    case GL_FLOAT_VEC4:
      return "vec4";
    case GL_FLOAT_MAT4:
      return "mat4";
    default:
      return fmt::format("GL type {:#06x}", type);
  }
}

std::logic_error missingUniform(const std::string& label, std::string_view name) {
  return std::logic_error(fmt::format(
      "program ({}) has no active uniform '{}': a mistyped name, or one this variant does not read "
      "(set it with setIfPresent, saying which variants leave it out)",
      label, name));
}

}  // namespace

const std::map<std::string, Program::ActiveUniform, std::less<>>& Program::activeUniforms() const {
  if (uniforms_) return *uniforms_;
  std::map<std::string, ActiveUniform, std::less<>> uniforms;
  GLint count = 0;
  glGetProgramInterfaceiv(id(), GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
  const std::array<GLenum, 4> properties = {GL_NAME_LENGTH, GL_TYPE, GL_ARRAY_SIZE, GL_LOCATION};
  for (GLint i = 0; i < count; ++i) {
    std::array<GLint, 4> values{};
    glGetProgramResourceiv(id(), GL_UNIFORM, GLuint(i), GLsizei(properties.size()),
                           properties.data(), GLsizei(values.size()), nullptr, values.data());
    if (values[3] < 0) continue;  // a member of a uniform block: no location of its own
    std::string name(std::size_t(std::max(values[0], 1)), '\0');
    glGetProgramResourceName(id(), GL_UNIFORM, GLuint(i), GLsizei(name.size()), nullptr,
                             name.data());
    name.resize(name.find('\0'));
    // An array is listed as its first element; it is set (and looked up) by its own name.
    if (name.ends_with("[0]")) name.resize(name.size() - 3);
    uniforms[name] = {values[3], GLenum(values[1]), values[2]};
  }
  uniforms_ = std::move(uniforms);
  return *uniforms_;
}

bool Program::hasUniform(std::string_view name) const {
  return activeUniforms().contains(name);
}

GLint Program::uniform(std::string_view name) const {
  const auto& uniforms = activeUniforms();
  const auto found = uniforms.find(name);
  if (found == uniforms.end()) throw missingUniform(label_, name);
  return found->second.location;
}

const Program::ActiveUniform& Program::active(std::string_view name,
                                              std::initializer_list<GLenum> types) const {
  const auto& uniforms = activeUniforms();
  const auto found = uniforms.find(name);
  if (found == uniforms.end()) throw missingUniform(label_, name);
  const ActiveUniform& u = found->second;
  if (std::find(types.begin(), types.end(), u.type) == types.end())
    throw std::logic_error(fmt::format("program ({}): uniform '{}' is a GLSL {}, set as {}", label_,
                                       name, glslTypeName(u.type), glslTypeName(*types.begin())));
  return u;
}

void Program::set(std::string_view name, int value) const {
  glProgramUniform1i(id(), active(name, {GL_INT, GL_BOOL}).location, value);
}

void Program::set(std::string_view name, unsigned value) const {
  glProgramUniform1ui(id(), active(name, {GL_UNSIGNED_INT, GL_BOOL}).location, value);
}

void Program::set(std::string_view name, float value) const {
  glProgramUniform1f(id(), active(name, {GL_FLOAT}).location, value);
}

void Program::set(std::string_view name, const glm::ivec2& value) const {
  glProgramUniform2i(id(), active(name, {GL_INT_VEC2, GL_BOOL_VEC2}).location, value.x, value.y);
}

void Program::set(std::string_view name, const glm::vec3& value) const {
  glProgramUniform3fv(id(), active(name, {GL_FLOAT_VEC3}).location, 1, glm::value_ptr(value));
}

void Program::set(std::string_view name, const glm::vec4& value) const {
  glProgramUniform4fv(id(), active(name, {GL_FLOAT_VEC4}).location, 1, glm::value_ptr(value));
}

void Program::set(std::string_view name, const glm::mat4& value) const {
  glProgramUniformMatrix4fv(id(), active(name, {GL_FLOAT_MAT4}).location, 1, GL_FALSE,
                            glm::value_ptr(value));
}

void Program::set(std::string_view name, std::span<const glm::vec3> values) const {
  const ActiveUniform& u = active(name, {GL_FLOAT_VEC3});
  if (GLint(values.size()) > u.elements)
    throw std::logic_error(fmt::format("program ({}): uniform '{}' holds {} vec3, set with {}",
                                       label_, name, u.elements, values.size()));
  if (!values.empty())
    glProgramUniform3fv(id(), u.location, GLsizei(values.size()), glm::value_ptr(values[0]));
}

}  // namespace gib::rt::gl
