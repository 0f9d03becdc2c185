#include "suites/run_environment.h"

#include "common/host_name.h"
#include "gib/version.h"
#include "reference/embree_scene.h"

#include <fmt/chrono.h>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <thread>

namespace gib::suites {

namespace {

// The "model name" line of /proc/cpuinfo (Linux); "unknown" elsewhere.
std::string cpuModel() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);) {
    if (line.rfind("model name", 0) != 0) continue;
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) break;
    const std::size_t start = line.find_first_not_of(' ', colon + 1);
    return start == std::string::npos ? "unknown" : line.substr(start);
  }
  return "unknown";
}

}  // namespace

std::string utcTimestamp() {
  const auto now = std::chrono::floor<std::chrono::seconds>(std::chrono::system_clock::now());
  return fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", now);
}

results::RunInfo describeEnvironment() {
  results::RunInfo info;
  info.gibench_version = kVersion;
  info.git_commit = kGitCommit;
  info.git_dirty = kGitDirty;
  info.build_type = GIB_BUILD_TYPE;
  info.host = hostName();
  info.cpu = cpuModel();
  info.cpu_cores = static_cast<int>(std::thread::hardware_concurrency());
  info.embree_version = ref::embreeVersion();
  return info;
}

}  // namespace gib::suites

namespace gib::suites {

namespace {

std::string environmentVariable(const char* name) {
  const char* value = std::getenv(name);
  return value ? value : "";
}

}  // namespace

results::JobExecution describeJobExecution() {
  results::JobExecution execution;
  execution.host = hostName();
  // Slurm names an array task by its array's job id and its index; a plain job by its own id.
  const std::string array = environmentVariable("SLURM_ARRAY_JOB_ID");
  const std::string task = environmentVariable("SLURM_ARRAY_TASK_ID");
  const std::string job = environmentVariable("SLURM_JOB_ID");
  if (!array.empty() && !task.empty())
    execution.scheduler_job = array + "_" + task;
  else
    execution.scheduler_job = job;
  // The submitting gibench exports its submission time (seconds since the epoch) to its tasks.
  const std::string submitted = environmentVariable(kSubmittedAtVariable);
  if (!submitted.empty()) {
    char* end = nullptr;
    const double at = std::strtod(submitted.c_str(), &end);
    if (end != submitted.c_str() && *end == '\0') {
      const double now =
          std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch())
              .count();
      execution.queue_seconds = std::max(0.0, now - at);
    }
  }
  return execution;
}

}  // namespace gib::suites
