// Small RAII owners of GL objects (unique_name.h; programs in program.h). Direct state access
// (GL 4.5) throughout, so nothing depends on what is bound.
#pragma once

#include "image/image.h"
#include "realtime/gl/gl.h"
#include "realtime/gl/program.h"
#include "realtime/gl/unique_name.h"

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace gib::rt::gl {

// An immutable-size buffer (glNamedBufferStorage); `flags` as for glBufferStorage
// (GL_DYNAMIC_STORAGE_BIT to allow update()).
class Buffer {
 public:
  Buffer() = default;
  Buffer(std::size_t bytes, const void* data, GLbitfield flags = GL_DYNAMIC_STORAGE_BIT);
  template <typename T>
  static Buffer fromVector(const std::vector<T>& values,
                           GLbitfield flags = GL_DYNAMIC_STORAGE_BIT) {
    return Buffer(values.size() * sizeof(T), values.data(), flags);
  }

  GLuint id() const { return name_.get(); }
  std::size_t bytes() const { return bytes_; }
  void update(std::size_t offset, std::size_t bytes, const void* data);
  void bindBase(GLenum target, GLuint index) const;  // GL_SHADER_STORAGE_BUFFER, GL_UNIFORM_BUFFER
  // Binds bytes [offset, offset + bytes); offset a multiple of the target's offset alignment.
  void bindRange(GLenum target, GLuint index, std::size_t offset, std::size_t bytes) const;

 private:
  UniqueName<detail::deleteBuffer> name_;
  std::size_t bytes_ = 0;
};

// The first `count` values of type T of a buffer, read back (waits for the GPU).
template <typename T>
std::vector<T> readBuffer(const Buffer& buffer, std::size_t count) {
  std::vector<T> values(count);
  glGetNamedBufferSubData(buffer.id(), 0, GLsizeiptr(count * sizeof(T)), values.data());
  return values;
}

// A texture with immutable storage. Float formats (GL_RGBA32F, GL_R32F, GL_RG32F, GL_RGBA16F,
// GL_DEPTH_COMPONENT32F) are what the techniques use; any sized format works.
class Texture {
 public:
  Texture() = default;
  static Texture make2D(GLenum format, int width, int height, int levels = 1);
  static Texture make2DArray(GLenum format, int width, int height, int layers, int levels = 1);
  static Texture make3D(GLenum format, int width, int height, int depth, int levels = 1);
  static Texture makeCube(GLenum format, int size, int levels = 1);
  static Texture makeCubeArray(GLenum format, int size, int cubes, int levels = 1);
  // A buffer texture over `buffer` (its texels in `format`, e.g. GL_RGBA32F): what a shader reads
  // with texelFetch(samplerBuffer, i). llvmpipe gathers texel fetches across a SIMD row, while it
  // loads storage buffers lane by lane, so hot per-pixel reads of a buffer go through one.
  static Texture makeBuffer(GLenum format, const Buffer& buffer);

  GLuint id() const { return name_.get(); }
  GLenum target() const { return target_; }
  GLenum format() const { return format_; }
  int width() const { return width_; }
  int height() const { return height_; }
  int depth() const { return depth_; }  // layers of an array, slices of a 3D texture, 6 of a cube
  int levels() const { return levels_; }

  // Sampling state: filter for minification and magnification, one wrap mode for all axes.
  void setFilter(GLenum min_filter, GLenum mag_filter);
  void setWrap(GLenum wrap);
  // Depth comparison for shadow samplers (GL_LEQUAL), or none.
  void setDepthCompare(bool enabled);
  void bind(GLuint unit) const { glBindTextureUnit(unit, id()); }

  // Uploads float RGBA (or fewer channels) into a 2D texture, or into one layer/slice/face.
  void upload(const float* values, GLenum pixel_format, int level = 0, int layer = 0);

 private:
  Texture(GLenum target, GLenum format, int width, int height, int depth, int levels);
  // Throws gib::EnvironmentError when the storage could not be allocated (GL_OUT_OF_MEMORY).
  void checkAllocated() const;
  UniqueName<detail::deleteTexture> name_;
  GLenum target_ = 0;
  GLenum format_ = 0;
  int width_ = 0, height_ = 0, depth_ = 1, levels_ = 1;
};

// A framebuffer over textures; checkComplete() throws std::logic_error naming the status.
class Framebuffer {
 public:
  Framebuffer();
  GLuint id() const { return name_.get(); }
  // Attaches a level of `texture`; `layer` ≥ 0 attaches one layer (array slice, cube face
  // 0..5, 3D slice), −1 the whole (layered) texture.
  void attachColor(int index, const Texture& texture, int level = 0, int layer = -1);
  void attachDepth(const Texture& texture, int level = 0, int layer = -1);
  // Enables the colour attachments 0..count−1 as draw buffers.
  void setDrawBuffers(int count);
  void checkComplete() const;
  void bind() const { glBindFramebuffer(GL_FRAMEBUFFER, id()); }

 private:
  UniqueName<detail::deleteFramebuffer> name_;
};

class VertexArray {
 public:
  VertexArray();
  GLuint id() const { return name_.get(); }
  void bind() const { glBindVertexArray(id()); }

 private:
  UniqueName<detail::deleteVertexArray> name_;
};

// A query object (GL_TIMESTAMP, GL_TIME_ELAPSED, GL_SAMPLES_PASSED, ...).
class Query {
 public:
  Query() = default;
  explicit Query(GLenum target);
  GLuint id() const { return name_.get(); }
  bool available() const;
  std::uint64_t result() const;  // waits until available

 private:
  UniqueName<detail::deleteQuery> name_;
};

// `layers` square colour images with a depth array behind one layered framebuffer: a batch of
// small views drawn at once, layer i by a draw's instance i (the layer chosen in the geometry
// shader). The colour filters nearest: it is read texel by texel.
class LayeredTarget {
 public:
  LayeredTarget(GLenum color_format, int size, int layers);

  const Texture& color() const { return color_; }
  const Framebuffer& framebuffer() const { return framebuffer_; }
  int size() const { return color_.width(); }
  int layers() const { return color_.depth(); }
  // The colour layers alone, for a target drawn once (its depth is freed with the rest).
  Texture takeColor() && { return std::move(color_); }

 private:
  Texture color_, depth_;
  Framebuffer framebuffer_;
};

// How many of `items` small images one batch of array layers holds: as many as `budget_bytes`
// allows at `bytes_per_layer` and the driver's GL_MAX_ARRAY_TEXTURE_LAYERS, at least one.
int layersPerBatch(int items, double bytes_per_layer, double budget_bytes);

// Reads colour attachment `index` of `framebuffer` (its first `channels` channels, as floats)
// into an image with pixel (0,0) at the top left: GL's rows start at the bottom.
image::Image readPixels(const Framebuffer& framebuffer, int index, int width, int height,
                        int channels = 3);
// Reads a whole 2D texture level the same way (RGBA or fewer channels).
image::Image readTexture(const Texture& texture, int channels, int level = 0);

}  // namespace gib::rt::gl
