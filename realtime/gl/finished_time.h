// Wall-clock time of GL work measured to its completion on the device: glFinish before the clock
// starts (so earlier work is not counted) and before it stops (so this work is). Shared by the
// technique runner's whole-phase timings and the benchmarks' manual iteration times.
#pragma once

#include "realtime/gl/gl.h"

#include <chrono>

namespace gib::rt::gl {

template <typename Work>
double finishedMilliseconds(Work&& work) {
  glFinish();
  const auto start = std::chrono::steady_clock::now();
  work();
  glFinish();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace gib::rt::gl
