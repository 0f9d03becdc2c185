#include "realtime/gl/stream_buffer.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace gib::rt::gl {

namespace {

constexpr GLbitfield kMapping = GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;

bool signalled(GLsync fence) {
  const GLenum status = glClientWaitSync(fence, 0, 0);
  return status == GL_ALREADY_SIGNALED || status == GL_CONDITION_SATISFIED;
}

// Waits until the GPU has passed `fence`, then deletes it.
void waitAndDelete(GLsync fence) {
  for (;;) {
    const GLenum status = glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, 1'000'000'000);
    if (status == GL_ALREADY_SIGNALED || status == GL_CONDITION_SATISFIED) break;
    if (status == GL_WAIT_FAILED) {
      glDeleteSync(fence);
      throw std::runtime_error("waiting for the GPU to release a stream buffer region failed");
    }
  }
  glDeleteSync(fence);
}

}  // namespace

StreamBuffer::StreamBuffer(StreamBuffer&& other) noexcept {
  *this = std::move(other);
}

StreamBuffer& StreamBuffer::operator=(StreamBuffer&& other) noexcept {
  if (this != &other) {
    release();
    buffer_ = std::move(other.buffer_);
    mapping_ = std::exchange(other.mapping_, nullptr);
    region_bytes_ = std::exchange(other.region_bytes_, 0);
    alignment_ = std::exchange(other.alignment_, 0);
    head_ = std::exchange(other.head_, 0);
    round_end_ = std::exchange(other.round_end_, 0);
    current_ = std::exchange(other.current_, -1);
    regions_ = std::exchange(other.regions_, kInitialRegions);
    fences_ = std::exchange(other.fences_, {});
  }
  return *this;
}

StreamBuffer::~StreamBuffer() {
  release();
}

void StreamBuffer::release() {
  // Deleting a fence or a buffer the GPU still uses is safe: the GL keeps them until it is done.
  for (GLsync& fence : fences_)
    if (fence) glDeleteSync(std::exchange(fence, nullptr));
  buffer_ = Buffer();
  mapping_ = nullptr;
}

std::size_t StreamBuffer::alignment() const {
  if (alignment_ == 0) {
    GLint uniform = 0, storage = 0;
    glGetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &uniform);
    glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &storage);
    alignment_ = std::size_t(std::max({uniform, storage, GLint(16)}));
  }
  return alignment_;
}

void StreamBuffer::allocate(std::size_t region_bytes, int regions) {
  release();
  region_bytes_ = alignedSize(region_bytes);
  regions_ = regions;
  const std::size_t bytes = region_bytes_ * std::size_t(regions_);
  buffer_ = Buffer(bytes, nullptr, kMapping);
  mapping_ =
      static_cast<std::byte*>(glMapNamedBufferRange(buffer_.id(), 0, GLsizeiptr(bytes), kMapping));
  if (!mapping_) throw std::runtime_error("the GL could not map a stream buffer persistently");
  fences_.assign(std::size_t(regions_), nullptr);
  current_ = 0;
  head_ = 0;
}

void StreamBuffer::beginRound(std::initializer_list<std::size_t> push_bytes) {
  std::size_t needed = 0;
  for (std::size_t bytes : push_bytes) needed += alignedSize(bytes);
  if (!buffer_.id()) {
    allocate(std::max(needed, kMinRegionBytes), regions_);
  } else if (head_ + needed > regionOffset(current_) + region_bytes_) {
    // The region is full: fence it (every command reading it has been issued), and go on in
    // the next one, once the GPU is done with it.
    fences_[std::size_t(current_)] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    const GLsync next = fences_[std::size_t((current_ + 1) % regions_)];
    if (needed > region_bytes_) {
      allocate(std::max(needed, 2 * region_bytes_), regions_);
    } else if (next && !signalled(next) &&
               2 * std::size_t(regions_) * region_bytes_ <= kMaxRingBytes) {
      allocate(region_bytes_, 2 * regions_);
    } else {
      current_ = (current_ + 1) % regions_;
      if (GLsync fence = std::exchange(fences_[std::size_t(current_)], nullptr))
        waitAndDelete(fence);
      head_ = regionOffset(current_);
    }
  }
  round_end_ = head_ + needed;
}

std::size_t StreamBuffer::push(const void* data, std::size_t bytes, std::size_t reserve) {
  if (!mapping_) throw std::logic_error("a push into a stream buffer before beginRound");
  const std::size_t taken = alignedSize(std::max(bytes, reserve));
  if (head_ + taken > round_end_)
    throw std::logic_error(
        fmt::format("a push of {} bytes beyond what its stream buffer round began with", taken));
  const std::size_t offset = head_;
  if (bytes) std::memcpy(mapping_ + offset, data, bytes);
  head_ += taken;
  return offset;
}

}  // namespace gib::rt::gl
