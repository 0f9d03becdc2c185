// The owner of one GL name (Filament's habit: an object owns its name, moves, never copies), which
// every GL object wrapper (objects.h, program.h) holds.
#pragma once

#include "realtime/gl/gl.h"

#include <utility>

namespace gib::rt::gl {

// Owns one GL name; `Delete` frees it. Moves leave the source empty (name 0).
template <void (*Delete)(GLuint)>
class UniqueName {
 public:
  UniqueName() = default;
  explicit UniqueName(GLuint name) : name_(name) {}
  ~UniqueName() { reset(); }
  UniqueName(UniqueName&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
  UniqueName& operator=(UniqueName&& other) noexcept {
    if (this != &other) {
      reset();
      name_ = std::exchange(other.name_, 0);
    }
    return *this;
  }
  UniqueName(const UniqueName&) = delete;
  UniqueName& operator=(const UniqueName&) = delete;

  GLuint get() const { return name_; }
  explicit operator bool() const { return name_ != 0; }
  void reset() {
    if (name_) Delete(name_);
    name_ = 0;
  }

 private:
  GLuint name_ = 0;
};

namespace detail {
void deleteBuffer(GLuint name);
void deleteTexture(GLuint name);
void deleteFramebuffer(GLuint name);
void deleteVertexArray(GLuint name);
void deleteProgram(GLuint name);
void deleteQuery(GLuint name);
}  // namespace detail

}  // namespace gib::rt::gl
