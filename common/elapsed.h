// Wall-clock milliseconds since a moment, for the phases a technique or command times itself
// (preparation stages, the records of a cache) outside the pass profiler.
#pragma once

#include <chrono>

namespace gib {

inline double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace gib
