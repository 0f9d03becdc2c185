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
#include <cstdint>
#include <deque>
#include <string>
#include <string_view>
#include <vector>

namespace gib::rt::gl {

class PassProfiler {
 public:
  // `latency`: frames whose queries may be in flight before beginFrame waits for the oldest
  // (0 waits for every frame). Throws std::invalid_argument if negative. `root_name` names the
  // unit being timed, passes[0] of the record: "frame", or "iteration" for the steps of an
  // iterative technique.
  explicit PassProfiler(bool precise = false, int latency = 4,
                        std::string_view root_name = kFramePass);

  // Ends its pass when destroyed. A destructor must not throw, so a pass that ends while one
  // opened after it is still open is reported by endFrame (std::logic_error).
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
  // scope does. Outside a frame it is a no-op, so techniques can profile unconditionally. The
  // name may not contain '/', which separates the names of a path; std::invalid_argument if so.
  [[nodiscard]] Scope pass(std::string_view name);
  // Ends the frame. std::logic_error if a pass is still open (the frame stays open, so its scopes
  // can still end), or if passes ended out of order (the frame is dropped).
  void endFrame();

  // Waits for the outstanding queries and returns everything measured so far; passes seen only
  // in warm-up frames are left out. Profiling may go on afterwards.
  ProfileRecord finish();

  bool precise() const { return precise_; }

 private:
  using Clock = std::chrono::steady_clock;
  struct Entry {
    std::size_t pass;  // index into record_.passes
    Query begin, end;
    Clock::time_point cpu_begin, cpu_end;
    std::uint64_t commands_begin = 0, commands_end = 0;  // gpuCommandsIssued() at each end
  };
  struct Frame {
    bool measured = false;
    std::vector<Entry> entries;  // entries[0] is the frame itself
  };

  std::size_t findOrAddPass(std::string_view name, std::size_t parent);
  std::size_t open(std::size_t pass);
  void close(std::size_t entry) noexcept;
  static bool ready(const Frame& frame);
  void collect(Frame& frame);
  void recycle(Frame& frame);
  Query takeQuery();

  bool precise_;
  int latency_;
  bool in_frame_ = false;
  bool misnested_ = false;  // a pass of the current frame ended before one opened inside it
  Frame current_;
  std::vector<std::size_t> open_stack_;  // entries of the current frame
  std::deque<Frame> in_flight_;
  std::vector<Query> spare_queries_;
  ProfileRecord record_;
  std::vector<std::size_t> parents_;  // parent of each pass in record_.passes (0 for the frame)
};

}  // namespace gib::rt::gl
