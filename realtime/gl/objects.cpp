#include "realtime/gl/objects.h"

#include "common/environment_error.h"
#include "realtime/gl/fault_injection.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gib::rt::gl {

namespace detail {
void deleteBuffer(GLuint name) {
  glDeleteBuffers(1, &name);
}
void deleteTexture(GLuint name) {
  glDeleteTextures(1, &name);
}
void deleteFramebuffer(GLuint name) {
  glDeleteFramebuffers(1, &name);
}
void deleteVertexArray(GLuint name) {
  glDeleteVertexArrays(1, &name);
}
void deleteProgram(GLuint name) {
  glDeleteProgram(name);
}
void deleteQuery(GLuint name) {
  glDeleteQueries(1, &name);
}
}  // namespace detail

namespace {

GLuint createName(void (*create)(GLsizei, GLuint*)) {
  GLuint name = 0;
  create(1, &name);
  return name;
}

GLenum pixelFormatFor(int channels) {
  switch (channels) {
    case 1:
      return GL_RED;
    case 2:
      return GL_RG;
    case 3:
      return GL_RGB;
    case 4:
      return GL_RGBA;
  }
  throw std::invalid_argument(fmt::format("cannot read {} channels; 1 to 4", channels));
}

// GL rows run bottom to top; the image type's run top to bottom.
void flipRows(image::Image& image) {
  const std::size_t row = std::size_t(image.width()) * std::size_t(image.channels());
  std::span<float> values = image.data();
  for (int y = 0; y < image.height() / 2; ++y)
    std::swap_ranges(values.begin() + std::ptrdiff_t(row * std::size_t(y)),
                     values.begin() + std::ptrdiff_t(row * std::size_t(y + 1)),
                     values.begin() + std::ptrdiff_t(row * std::size_t(image.height() - 1 - y)));
}

}  // namespace

Buffer::Buffer(std::size_t bytes, const void* data, GLbitfield flags)
    : name_(createName(glCreateBuffers)), bytes_(bytes) {
  // A zero-sized store is not allowed; one byte keeps empty scene parts bindable.
  glNamedBufferStorage(name_.get(), GLsizeiptr(std::max<std::size_t>(bytes, 1)),
                       bytes ? data : nullptr, flags);
}

void Buffer::update(std::size_t offset, std::size_t bytes, const void* data) {
  glNamedBufferSubData(id(), GLintptr(offset), GLsizeiptr(bytes), data);
}

void Buffer::bindBase(GLenum target, GLuint index) const {
  glBindBufferBase(target, index, id());
}

void Buffer::bindRange(GLenum target, GLuint index, std::size_t offset, std::size_t bytes) const {
  glBindBufferRange(target, index, id(), GLintptr(offset), GLsizeiptr(bytes));
}

Texture::Texture(GLenum target, GLenum format, int width, int height, int depth, int levels)
    : target_(target),
      format_(format),
      width_(width),
      height_(height),
      depth_(depth),
      levels_(levels) {
  GLuint name = 0;
  glCreateTextures(target, 1, &name);
  name_ = UniqueName<detail::deleteTexture>(name);
  if (target == GL_TEXTURE_BUFFER) return;  // no sampling state: texelFetch only
  const bool filterable = levels > 1;
  glTextureParameteri(name, GL_TEXTURE_MIN_FILTER,
                      filterable ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
  glTextureParameteri(name, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(name, GL_TEXTURE_MAX_LEVEL, levels - 1);
  setWrap(GL_CLAMP_TO_EDGE);
}

// The driver reports a texture it could not allocate as GL_OUT_OF_MEMORY, and a technique drawing
// into it would go on silently: check once, where it is made (not in a frame).
void Texture::checkAllocated() const {
  if (!glFaultInjected(GlFault::kTextureOutOfMemory) && glGetError() != GL_OUT_OF_MEMORY) return;
  throw EnvironmentError(fmt::format(
      "out of GPU memory for a {}x{}x{} texture of format 0x{:x} ({} levels); use a smaller "
      "image or parameters, or a GPU with more memory",
      width_, height_, depth_, format_, levels_));
}

Texture Texture::make2D(GLenum format, int width, int height, int levels) {
  Texture t(GL_TEXTURE_2D, format, width, height, 1, levels);
  glTextureStorage2D(t.id(), levels, format, width, height);
  t.checkAllocated();
  return t;
}

Texture Texture::make2DArray(GLenum format, int width, int height, int layers, int levels) {
  Texture t(GL_TEXTURE_2D_ARRAY, format, width, height, layers, levels);
  glTextureStorage3D(t.id(), levels, format, width, height, layers);
  t.checkAllocated();
  return t;
}

Texture Texture::make3D(GLenum format, int width, int height, int depth, int levels) {
  Texture t(GL_TEXTURE_3D, format, width, height, depth, levels);
  glTextureStorage3D(t.id(), levels, format, width, height, depth);
  t.checkAllocated();
  return t;
}

Texture Texture::makeCube(GLenum format, int size, int levels) {
  Texture t(GL_TEXTURE_CUBE_MAP, format, size, size, 6, levels);
  glTextureStorage2D(t.id(), levels, format, size, size);
  t.checkAllocated();
  return t;
}

Texture Texture::makeCubeArray(GLenum format, int size, int cubes, int levels) {
  Texture t(GL_TEXTURE_CUBE_MAP_ARRAY, format, size, size, 6 * cubes, levels);
  glTextureStorage3D(t.id(), levels, format, size, size, 6 * cubes);
  t.checkAllocated();
  return t;
}

Texture Texture::makeBuffer(GLenum format, const Buffer& buffer) {
  int texel_bytes = 0;
  if (format == GL_RGBA32F) texel_bytes = 16;
  if (format == GL_RG32F) texel_bytes = 8;
  if (format == GL_R32F || format == GL_R32UI) texel_bytes = 4;
  if (format == GL_R8UI) texel_bytes = 1;
  if (texel_bytes == 0)
    throw std::invalid_argument(fmt::format("buffer texture of format 0x{:x}", format));
  GLint bytes = 0;
  glGetNamedBufferParameteriv(buffer.id(), GL_BUFFER_SIZE, &bytes);
  Texture t(GL_TEXTURE_BUFFER, format, bytes / texel_bytes, 1, 1, 1);
  glTextureBuffer(t.id(), format, buffer.id());
  return t;
}

void Texture::setFilter(GLenum min_filter, GLenum mag_filter) {
  glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, GLint(min_filter));
  glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, GLint(mag_filter));
}

void Texture::setWrap(GLenum wrap) {
  glTextureParameteri(id(), GL_TEXTURE_WRAP_S, GLint(wrap));
  glTextureParameteri(id(), GL_TEXTURE_WRAP_T, GLint(wrap));
  glTextureParameteri(id(), GL_TEXTURE_WRAP_R, GLint(wrap));
}

void Texture::setDepthCompare(bool enabled) {
  glTextureParameteri(id(), GL_TEXTURE_COMPARE_MODE, enabled ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
  glTextureParameteri(id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
}

void Texture::upload(const float* values, GLenum pixel_format, int level, int layer) {
  const int w = std::max(1, width_ >> level), h = std::max(1, height_ >> level);
  if (target_ == GL_TEXTURE_2D)
    glTextureSubImage2D(id(), level, 0, 0, w, h, pixel_format, GL_FLOAT, values);
  else
    glTextureSubImage3D(id(), level, 0, 0, layer, w, h, 1, pixel_format, GL_FLOAT, values);
}

Framebuffer::Framebuffer() : name_(createName(glCreateFramebuffers)) {}

void Framebuffer::attachColor(int index, const Texture& texture, int level, int layer) {
  const GLenum attachment = GL_COLOR_ATTACHMENT0 + GLenum(index);
  if (layer < 0)
    glNamedFramebufferTexture(id(), attachment, texture.id(), level);
  else
    glNamedFramebufferTextureLayer(id(), attachment, texture.id(), level, layer);
}

void Framebuffer::attachDepth(const Texture& texture, int level, int layer) {
  if (layer < 0)
    glNamedFramebufferTexture(id(), GL_DEPTH_ATTACHMENT, texture.id(), level);
  else
    glNamedFramebufferTextureLayer(id(), GL_DEPTH_ATTACHMENT, texture.id(), level, layer);
}

void Framebuffer::setDrawBuffers(int count) {
  std::vector<GLenum> buffers;
  for (int i = 0; i < count; ++i) buffers.push_back(GL_COLOR_ATTACHMENT0 + GLenum(i));
  if (count == 0)
    glNamedFramebufferDrawBuffer(id(), GL_NONE);
  else
    glNamedFramebufferDrawBuffers(id(), count, buffers.data());
}

void Framebuffer::checkComplete() const {
  const GLenum status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::logic_error(
        fmt::format("framebuffer {} is incomplete (status 0x{:04x})", id(), status));
}

VertexArray::VertexArray() : name_(createName(glCreateVertexArrays)) {}

Query::Query(GLenum target) {
  GLuint name = 0;
  glCreateQueries(target, 1, &name);
  name_ = UniqueName<detail::deleteQuery>(name);
}

bool Query::available() const {
  GLint available = 0;
  glGetQueryObjectiv(id(), GL_QUERY_RESULT_AVAILABLE, &available);
  return available != 0;
}

std::uint64_t Query::result() const {
  GLuint64 value = 0;
  glGetQueryObjectui64v(id(), GL_QUERY_RESULT, &value);
  return value;
}

LayeredTarget::LayeredTarget(GLenum color_format, int size, int layers)
    : color_(Texture::make2DArray(color_format, size, size, layers)),
      depth_(Texture::make2DArray(GL_DEPTH_COMPONENT32F, size, size, layers)) {
  color_.setFilter(GL_NEAREST, GL_NEAREST);
  framebuffer_.attachColor(0, color_);
  framebuffer_.attachDepth(depth_);
  framebuffer_.setDrawBuffers(1);
  framebuffer_.checkComplete();
}

int layersPerBatch(int items, double bytes_per_layer, double budget_bytes) {
  GLint max_layers = 0;
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &max_layers);
  const double fit = std::floor(budget_bytes / bytes_per_layer);
  return int(std::max(1.0, std::min({double(max_layers), fit, double(items)})));
}

image::Image readPixels(const Framebuffer& framebuffer, int index, int width, int height,
                        int channels) {
  image::Image image(width, height, channels);
  glNamedFramebufferReadBuffer(framebuffer.id(), GL_COLOR_ATTACHMENT0 + GLenum(index));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadnPixels(0, 0, width, height, pixelFormatFor(channels), GL_FLOAT,
                GLsizei(image.data().size() * sizeof(float)), image.data().data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  flipRows(image);
  return image;
}

image::Image readTexture(const Texture& texture, int channels, int level) {
  const int w = std::max(1, texture.width() >> level), h = std::max(1, texture.height() >> level);
  image::Image image(w, h, channels);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(texture.id(), level, pixelFormatFor(channels), GL_FLOAT,
                    GLsizei(image.data().size() * sizeof(float)), image.data().data());
  flipRows(image);
  return image;
}

}  // namespace gib::rt::gl
