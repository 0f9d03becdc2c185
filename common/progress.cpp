#include "progress.h"

#include <unistd.h>

#include <fmt/format.h>
#include <cstdio>

namespace gib {

bool ProgressBar::stderrIsTerminal() {
  return isatty(STDERR_FILENO) == 1;
}

ProgressBar::ProgressBar(std::string label, std::uint64_t total, std::string unit)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(total),
      enabled_(stderrIsTerminal()),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

ProgressBar::~ProgressBar() {
  finish();
}

void ProgressBar::advance(std::uint64_t units) {
  std::lock_guard lock(mutex_);
  done_ += units;
  if (!enabled_) return;
  auto now = std::chrono::steady_clock::now();
  if (now - last_draw_ < std::chrono::milliseconds(100) && done_ < total_) return;
  last_draw_ = now;
  draw(false);
}

void ProgressBar::finish() {
  std::lock_guard lock(mutex_);
  if (finished_) return;
  finished_ = true;
  if (enabled_) draw(true);
}

void ProgressBar::draw(bool final) {
  constexpr int kWidth = 30;
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  double fraction = total_ > 0 ? double(done_) / double(total_) : 1.0;
  int filled = static_cast<int>(fraction * kWidth);
  std::string bar(filled, '=');
  if (filled < kWidth) bar += '>' + std::string(kWidth - filled - 1, ' ');
  double rate = seconds > 0 ? double(done_) / seconds : 0.0;
  double eta = rate > 0 ? double(total_ - done_) / rate : 0.0;
  std::string line =
      fmt::format("\r{} [{}] {:3.0f}% {}{}/s {} {:.0f}s ", label_, bar, 100.0 * fraction,
                  formatSi(rate), unit_, final ? "took" : "ETA", final ? seconds : eta);
  std::fputs(line.c_str(), stderr);
  if (final) std::fputc('\n', stderr);
  std::fflush(stderr);
}

std::string formatSi(double value) {
  if (value >= 1e9) return fmt::format("{:.2f} G", value / 1e9);
  if (value >= 1e6) return fmt::format("{:.2f} M", value / 1e6);
  if (value >= 1e3) return fmt::format("{:.2f} k", value / 1e3);
  return fmt::format("{:.2f} ", value);
}

}  // namespace gib
