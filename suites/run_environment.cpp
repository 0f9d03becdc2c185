#include "suites/run_environment.h"

#include "gib/version.h"
#include "reference/embree_scene.h"

#include <fmt/chrono.h>
#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <thread>

namespace gib::suites {

namespace {

std::string hostName() {
  char name[256] = {};
  if (gethostname(name, sizeof name - 1) != 0) return "unknown";
  return name;
}

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
