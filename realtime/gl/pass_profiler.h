// Per-pass timing in Falcor's manner: named, nestable passes, GPU time from timestamp queries
// read back frames later without stalling the pipeline, and in precise mode CPU time around a
// glFinish at each pass boundary (exact on any driver, at the cost of the overlap between passes).
//
//   PassProfiler profiler(precise);
//   for (frame ...) {
//     profiler.beginFrame(measured);
//     { auto scope = profiler.pass("shadow map"); ... }
//     profiler.endFrame();
//   }
//   ProfileRecord record = profiler.finish();
//
// GL_TIME_ELAPSED queries cannot nest (one may be active at a time), so each pass brackets itself
// with two GL_TIMESTAMP queries instead: the same clock, and passes nest freely.
#pragma once

#include "realtime/gl/objects.h"
#include "realtime/gl/pass_record.h"

#include <chrono>
#include <deque>
#include <string>
#include <string_view>
#include <vector>

namespace gib::rt::gl {

class PassProfiler {
 public:
  // `latency`: frames whose queries may be in flight before beginFrame waits for the oldest.
  explicit PassProfiler(bool precise = false, int latency = 4);

  class Scope {
   public:
    Scope(Scope&& other) noexcept;
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;
    Scope& operator=(Scope&&) = delete;
    ~Scope();

   private:
    friend class PassProfiler;
    Scope(PassProfiler* profiler, std::size_t entry) : profiler_(profiler), entry_(entry) {}
    PassProfiler* profiler_;
    std::size_t entry_;
  };

  // Starts a frame; a frame with measured = false is a warm-up frame and is not recorded.
  void beginFrame(bool measured = true);
  // Opens a pass inside the current frame (or inside the innermost open pass); it ends when the
  // scope does. Outside a frame it is a no-op, so techniques can profile unconditionally.
  [[nodiscard]] Scope pass(std::string_view name);
  void endFrame();

  // Waits for the outstanding queries and returns everything measured.
  ProfileRecord finish();

  bool precise() const { return precise_; }

 private:
  using Clock = std::chrono::steady_clock;
  struct Entry {
    std::size_t pass;  // index into record_.passes
    Query begin, end;
    Clock::time_point cpu_begin, cpu_end;
  };
  struct Frame {
    bool measured = false;
    std::vector<Entry> entries;
  };

  std::size_t findOrAddPass(std::string_view name, std::string_view parent_path, int depth);
  std::size_t open(std::string_view name);
  void close(std::size_t entry);
  void collect(Frame& frame);
  Query takeQuery();

  bool precise_;
  int latency_;
  bool in_frame_ = false;
  Frame current_;
  std::vector<std::size_t> open_stack_;  // entries of the current frame
  std::deque<Frame> in_flight_;
  std::vector<Query> spare_queries_;
  ProfileRecord record_;
};

}  // namespace gib::rt::gl
