#include "realtime/gl/pass_profiler.h"

#include "realtime/gl/gpu_commands.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace gib::rt::gl {

PassProfiler::PassProfiler(bool precise, int latency, std::string_view root_name)
    : precise_(precise), latency_(latency) {
  if (latency < 0) throw std::invalid_argument("profiler latency must be 0 or more frames");
  if (root_name.empty() || root_name.find('/') != std::string_view::npos)
    throw std::invalid_argument("the profiler's root name must be non-empty and without '/'");
  record_.precise = precise;
  record_.reported_clock = precise ? "cpu" : "gpu";
  record_.passes.push_back(
      PassRecord{std::string(root_name), std::string(root_name), 0, {}, {}, {}, {}});
  parents_.push_back(0);
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

std::size_t PassProfiler::findOrAddPass(std::string_view name, std::size_t parent) {
  // Compared by parent and name rather than by path, so that a pass seen before (every pass
  // after the first frame) costs no string building.
  for (std::size_t i = 1; i < record_.passes.size(); ++i)
    if (parents_[i] == parent && record_.passes[i].name == name) return i;
  const PassRecord& up = record_.passes[parent];
  record_.passes.push_back(PassRecord{
      std::string(name), fmt::format("{}/{}", up.path, name), up.depth + 1, {}, {}, {}, {}});
  parents_.push_back(parent);
  return record_.passes.size() - 1;
}

std::size_t PassProfiler::open(std::size_t pass) {
  Entry entry{pass, takeQuery(), takeQuery(), {}, {}, gpuCommandsIssued(), 0};
  if (precise_) glFinish();
  entry.cpu_begin = Clock::now();
  glQueryCounter(entry.begin.id(), GL_TIMESTAMP);
  current_.entries.push_back(std::move(entry));
  open_stack_.push_back(current_.entries.size() - 1);
  return current_.entries.size() - 1;
}

void PassProfiler::close(std::size_t index) noexcept {
  Entry& entry = current_.entries[index];
  glQueryCounter(entry.end.id(), GL_TIMESTAMP);
  entry.commands_end = gpuCommandsIssued();
  if (precise_) glFinish();
  entry.cpu_end = Clock::now();
  // Called from a destructor, so a pass ending before one opened inside it cannot throw here:
  // it is noted, and endFrame reports it.
  const auto it = std::find(open_stack_.begin(), open_stack_.end(), index);
  if (it == open_stack_.end()) return;
  if (it + 1 != open_stack_.end()) misnested_ = true;
  open_stack_.erase(it);
}

bool PassProfiler::ready(const Frame& frame) {
  // GL does not promise that queries become available in the order they were issued, so every
  // one is asked; entries[0] (the frame: first begin, last end) usually answers "not yet" first.
  return std::all_of(frame.entries.begin(), frame.entries.end(), [](const Entry& entry) {
    return entry.begin.available() && entry.end.available();
  });
}

void PassProfiler::beginFrame(bool measured) {
  if (in_frame_) throw std::logic_error("beginFrame called twice without endFrame");
  // Collect frames whose queries have landed; wait only when too many are in flight.
  while (!in_flight_.empty()) {
    if (int(in_flight_.size()) < latency_ && !ready(in_flight_.front())) break;
    collect(in_flight_.front());
    in_flight_.pop_front();
  }
  in_frame_ = true;
  current_ = Frame{measured, {}};
  open(0);
}

PassProfiler::Scope PassProfiler::pass(std::string_view name) {
  if (!in_frame_) return Scope(nullptr, 0);
  if (name.find('/') != std::string_view::npos)
    throw std::invalid_argument(fmt::format("pass name '{}' contains '/'", name));
  const std::size_t parent = current_.entries[open_stack_.back()].pass;
  return Scope(this, open(findOrAddPass(name, parent)));
}

void PassProfiler::endFrame() {
  if (!in_frame_) throw std::logic_error("endFrame without beginFrame");
  if (open_stack_.size() > 1) {
    const std::size_t pass = current_.entries[open_stack_.back()].pass;
    throw std::logic_error(
        fmt::format("pass '{}' is still open at the end of the frame", record_.passes[pass].path));
  }
  close(0);
  in_frame_ = false;
  Frame frame = std::exchange(current_, Frame{});
  if (std::exchange(misnested_, false)) {
    recycle(frame);
    throw std::logic_error(
        "profiler passes must end in the reverse order of their start; the frame is dropped");
  }
  in_flight_.push_back(std::move(frame));
}

void PassProfiler::collect(Frame& frame) {
  if (!frame.measured) {
    ++record_.warmup_frames;
    recycle(frame);
    return;
  }
  // Sum repeated entries of a pass; passes absent from this frame get zero.
  const std::size_t passes = record_.passes.size();
  std::vector<double> gpu(passes, 0.0), cpu(passes, 0.0);
  std::vector<int> calls(passes, 0), commands(passes, 0);
  for (const Entry& entry : frame.entries) {
    commands[entry.pass] += int(entry.commands_end - entry.commands_begin);
    const std::uint64_t begin = entry.begin.result(), end = entry.end.result();
    gpu[entry.pass] += end > begin ? double(end - begin) * 1e-6 : 0.0;
    cpu[entry.pass] +=
        std::chrono::duration<double, std::milli>(entry.cpu_end - entry.cpu_begin).count();
    ++calls[entry.pass];
  }
  const std::size_t earlier = std::size_t(record_.measured_frames);
  for (std::size_t p = 0; p < passes; ++p) {
    PassRecord& pass = record_.passes[p];
    pass.gpu_ms.resize(earlier, 0.0);  // a pass first seen now was absent before
    pass.gpu_ms.push_back(gpu[p]);
    pass.calls.resize(earlier, 0);
    pass.calls.push_back(calls[p]);
    pass.gpu_commands.resize(earlier, 0);
    pass.gpu_commands.push_back(commands[p]);
    if (precise_) {  // without precise mode there is no CPU clock to keep
      pass.cpu_ms.resize(earlier, 0.0);
      pass.cpu_ms.push_back(cpu[p]);
    }
  }
  ++record_.measured_frames;
  recycle(frame);
}

void PassProfiler::recycle(Frame& frame) {
  // Reissuing a query whose result was never read is allowed: the new result replaces it.
  for (Entry& entry : frame.entries) {
    spare_queries_.push_back(std::move(entry.begin));
    spare_queries_.push_back(std::move(entry.end));
  }
  frame.entries.clear();
}

ProfileRecord PassProfiler::finish() {
  if (in_frame_) throw std::logic_error("finish called inside a frame");
  while (!in_flight_.empty()) {
    collect(in_flight_.front());
    in_flight_.pop_front();
  }
  ProfileRecord out = record_;
  // A pass seen only in warm-up frames (one-off set-up work) would read as a pass that costs 0.
  std::erase_if(out.passes, [&](const PassRecord& pass) {
    return pass.depth > 0 &&
           std::all_of(pass.calls.begin(), pass.calls.end(), [](int calls) { return calls == 0; });
  });
  return out;
}

}  // namespace gib::rt::gl
