// What the pass profiler measured, as plain data (no GL): the harness and the metrics layer
// summarise and store it without touching OpenGL.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace gib::rt {

// The roots of a record's pass paths: what one measured unit is.
inline constexpr std::string_view kFramePass = "frame";          // a frame (every technique)
inline constexpr std::string_view kIterationPass = "iteration";  // a step of an iterative one

// One named pass over the measured frames. A pass entered several times in a frame (a shadow
// map per light sample) counts once per frame with the sum of its entries.
struct PassRecord {
  std::string name;  // as given to PassProfiler::pass
  std::string path;  // "frame/lights/shadow map": names of the enclosing passes and this one
  int depth = 0;     // 0 for the frame itself
  std::vector<double> gpu_ms;  // per measured frame, from GL timestamp queries
  std::vector<double> cpu_ms;  // per measured frame, wall clock around glFinish (precise mode)
  std::vector<int> calls;      // entries per measured frame
  // Draws and compute dispatches issued inside the pass (its inner passes' included) per
  // measured frame (gl/gpu_commands.h). Empty in records written before they were counted.
  std::vector<int> gpu_commands;
};

struct ProfileRecord {
  // The clock the summaries report: "gpu" (timestamp queries) or "cpu" (wall clock between
  // glFinish calls, precise mode). llvmpipe's queries miss vertex work, so on a software
  // renderer the harness reports "cpu".
  std::string reported_clock = "gpu";
  bool precise = false;
  int warmup_frames = 0;
  int measured_frames = 0;
  std::vector<PassRecord> passes;  // passes[0] is the whole frame; the rest in first-seen order

  // The per-frame times of the reported clock.
  const std::vector<double>& reported(const PassRecord& pass) const {
    return reported_clock == "cpu" ? pass.cpu_ms : pass.gpu_ms;
  }
};

}  // namespace gib::rt
