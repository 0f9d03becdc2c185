// A progress bar for long work, drawn on stderr only when stderr is a terminal
// (docs/architecture.md: logs and progress go to stderr; a pipe or CI log stays quiet).
#pragma once

#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace gib {

class ProgressBar {
 public:
  // `total` units of work (e.g. samples); `unit` names them in the rate ("samples/s").
  ProgressBar(std::string label, std::uint64_t total, std::string unit);
  ~ProgressBar();

  // Thread-safe; redraws at most ten times a second.
  void advance(std::uint64_t units);
  // Draws the final state and moves to a new line.
  void finish();

  static bool stderrIsTerminal();

 private:
  void draw(bool final);

  std::string label_;
  std::string unit_;
  std::uint64_t total_;
  std::uint64_t done_ = 0;
  bool enabled_;
  bool finished_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
  std::mutex mutex_;
};

// "12.3 M" style formatting of a rate.
std::string formatSi(double value);

}  // namespace gib
