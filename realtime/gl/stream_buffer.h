// Data the CPU writes every frame (a batch's light samples and shadow faces, the probe views'
// blocks, multi-draw records) written straight into persistently mapped buffer memory (GL 4.4
// buffer storage, coherent) instead of through glBufferSubData, which makes a driver copy the data
// or wait until the GPU no longer reads the buffer it replaces.
//
// A caller begins a round of work (a shadow batch, a frame's probe views), pushes its arrays,
// binds their ranges and issues the commands that read them. Rounds follow one another through
// a ring of a few large regions, so nothing is written over while a queued command may read it.
// A fence is set only when a round moves on to the next region (a fence can make a driver flush
// its queue, llvmpipe's for one, so not one per round), and a region is written again only once
// the fence set when it was left has signalled. Where the GPU is still reading the region next
// in turn, the ring doubles its regions rather than wait, within kMaxRingBytes.
#pragma once

#include "realtime/gl/objects.h"

#include <cstddef>
#include <initializer_list>
#include <vector>

namespace gib::rt::gl {

class StreamBuffer {
 public:
  // Regions a ring starts with, and the least bytes of one: a few frames of rounds of a few
  // tens of KiB each before a fence.
  static constexpr int kInitialRegions = 3;
  static constexpr std::size_t kMinRegionBytes = 256u << 10;
  // A ring grows its regions only while it stays within this size; past it, rounds wait.
  static constexpr std::size_t kMaxRingBytes = 64u << 20;

  StreamBuffer() = default;
  StreamBuffer(StreamBuffer&&) noexcept;
  StreamBuffer& operator=(StreamBuffer&&) noexcept;
  StreamBuffer(const StreamBuffer&) = delete;
  StreamBuffer& operator=(const StreamBuffer&) = delete;
  ~StreamBuffer();

  // Begins a round with room for pushes taking these sizes in bytes, after the previous round
  // (whose commands have all been issued by now) or, where it does not fit, at the start of the
  // next region. A round larger than a region gets a ring of larger regions. (A ring replaced by
  // a larger one lives on in the GL until the GPU is done with it.)
  void beginRound(std::initializer_list<std::size_t> push_bytes);
  // Copies `bytes` at the round's next offset a uniform or storage block may start at, taking at
  // least `reserve` bytes there (a uniform block is bound at its whole declared size, even where
  // a round fills only part of its array), and returns that offset in the buffer.
  std::size_t push(const void* data, std::size_t bytes, std::size_t reserve = 0);
  template <typename T>
  std::size_t push(const std::vector<T>& values, std::size_t reserve = 0) {
    return push(values.data(), values.size() * sizeof(T), reserve);
  }

  GLuint id() const { return buffer_.id(); }
  void bindRange(GLenum target, GLuint index, std::size_t offset, std::size_t bytes) const {
    buffer_.bindRange(target, index, offset, bytes);
  }

  // What pushes start at: a multiple of the larger of the GL's uniform and storage block offset
  // alignments (asked once). A caller laying out several blocks in one push spaces them so.
  std::size_t alignment() const;
  std::size_t alignedSize(std::size_t bytes) const {
    return (bytes + alignment() - 1) / alignment() * alignment();
  }

  // The region the current round writes, where region r starts, bytes per region and regions in
  // the ring (tests).
  int currentRegion() const { return current_; }
  std::size_t regionOffset(int region) const { return std::size_t(region) * region_bytes_; }
  std::size_t regionBytes() const { return region_bytes_; }
  int regions() const { return regions_; }

 private:
  void allocate(std::size_t region_bytes, int regions);
  void release();

  Buffer buffer_;
  std::byte* mapping_ = nullptr;
  std::size_t region_bytes_ = 0;
  mutable std::size_t alignment_ = 0;     // 0 until first asked
  std::size_t head_ = 0, round_end_ = 0;  // the next push and the end of the current round
  int current_ = -1, regions_ = kInitialRegions;
  std::vector<GLsync> fences_;  // per region: set when it was left, or null
};

}  // namespace gib::rt::gl
