#include "realtime/gl/pass_profiler.h"

#include <stdexcept>

namespace gib::rt::gl {

PassProfiler::PassProfiler(bool precise, int latency) : precise_(precise), latency_(latency) {
  record_.precise = precise;
  record_.reported_clock = precise ? "cpu" : "gpu";
  record_.passes.push_back(PassRecord{"frame", "frame", 0, {}, {}, {}});
}

PassProfiler::Scope::Scope(Scope&& other) noexcept
    : profiler_(std::exchange(other.profiler_, nullptr)), entry_(other.entry_) {}

PassProfiler::Scope::~Scope() {
  if (profiler_) profiler_->close(entry_);
}

Query PassProfiler::takeQuery() {
  if (spare_queries_.empty()) return Query(GL_TIMESTAMP);
  Query q = std::move(spare_queries_.back());
  spare_queries_.pop_back();
  return q;
}

std::size_t PassProfiler::findOrAddPass(std::string_view name, std::string_view parent_path,
                                        int depth) {
  std::string path = std::string(parent_path) + "/" + std::string(name);
  for (std::size_t i = 0; i < record_.passes.size(); ++i)
    if (record_.passes[i].path == path) return i;
  record_.passes.push_back(PassRecord{std::string(name), path, depth, {}, {}, {}});
  return record_.passes.size() - 1;
}

std::size_t PassProfiler::open(std::string_view name) {
  std::size_t pass = 0;
  if (!current_.entries.empty()) {
    const Entry& parent = current_.entries[open_stack_.back()];
    const PassRecord& parent_record = record_.passes[parent.pass];
    pass = findOrAddPass(name, parent_record.path, parent_record.depth + 1);
  }
  Entry entry{pass, takeQuery(), takeQuery(), {}, {}};
  if (precise_) glFinish();
  entry.cpu_begin = Clock::now();
  glQueryCounter(entry.begin.id(), GL_TIMESTAMP);
  current_.entries.push_back(std::move(entry));
  open_stack_.push_back(current_.entries.size() - 1);
  return current_.entries.size() - 1;
}

void PassProfiler::close(std::size_t index) {
  if (open_stack_.empty() || open_stack_.back() != index)
    throw std::logic_error("profiler passes must end in the reverse order of their start");
  Entry& entry = current_.entries[index];
  glQueryCounter(entry.end.id(), GL_TIMESTAMP);
  if (precise_) glFinish();
  entry.cpu_end = Clock::now();
  open_stack_.pop_back();
}

void PassProfiler::beginFrame(bool measured) {
  if (in_frame_) throw std::logic_error("beginFrame called twice without endFrame");
  // Collect frames whose queries have landed; wait only when too many are in flight.
  while (!in_flight_.empty()) {
    Frame& oldest = in_flight_.front();
    const bool ready = oldest.entries.empty() || oldest.entries.back().end.available();
    if (!ready && int(in_flight_.size()) < latency_) break;
    collect(oldest);
    in_flight_.pop_front();
  }
  in_frame_ = true;
  current_ = Frame{measured, {}};
  open(record_.passes[0].name);
}

PassProfiler::Scope PassProfiler::pass(std::string_view name) {
  if (!in_frame_) return Scope(nullptr, 0);
  return Scope(this, open(name));
}

void PassProfiler::endFrame() {
  if (!in_frame_) throw std::logic_error("endFrame without beginFrame");
  close(0);
  if (!open_stack_.empty()) throw std::logic_error("a pass is still open at the end of the frame");
  in_frame_ = false;
  in_flight_.push_back(std::move(current_));
  current_ = Frame{};
}

void PassProfiler::collect(Frame& frame) {
  if (frame.measured) {
    // Sum repeated entries of a pass; passes absent from this frame get zero.
    std::vector<double> gpu(record_.passes.size(), 0.0), cpu(record_.passes.size(), 0.0);
    std::vector<int> calls(record_.passes.size(), 0);
    for (Entry& entry : frame.entries) {
      const std::uint64_t begin = entry.begin.result(), end = entry.end.result();
      gpu[entry.pass] += end > begin ? double(end - begin) * 1e-6 : 0.0;
      cpu[entry.pass] +=
          std::chrono::duration<double, std::milli>(entry.cpu_end - entry.cpu_begin).count();
      ++calls[entry.pass];
    }
    const std::size_t earlier = std::size_t(record_.measured_frames);
    for (std::size_t p = 0; p < record_.passes.size(); ++p) {
      PassRecord& pass = record_.passes[p];
      pass.gpu_ms.resize(earlier, 0.0);  // a pass first seen now was absent before
      pass.cpu_ms.resize(earlier, 0.0);
      pass.calls.resize(earlier, 0);
      pass.gpu_ms.push_back(gpu[p]);
      if (precise_) pass.cpu_ms.push_back(cpu[p]);
      pass.calls.push_back(calls[p]);
    }
    ++record_.measured_frames;
  } else {
    ++record_.warmup_frames;
  }
  for (Entry& entry : frame.entries) {
    spare_queries_.push_back(std::move(entry.begin));
    spare_queries_.push_back(std::move(entry.end));
  }
}

ProfileRecord PassProfiler::finish() {
  if (in_frame_) throw std::logic_error("finish called inside a frame");
  while (!in_flight_.empty()) {
    collect(in_flight_.front());
    in_flight_.pop_front();
  }
  // Without precise mode there is no CPU clock to keep.
  if (!precise_)
    for (PassRecord& pass : record_.passes) pass.cpu_ms.clear();
  return record_;
}

}  // namespace gib::rt::gl
