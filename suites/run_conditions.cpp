#include "suites/run_conditions.h"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <string>

namespace gib::suites {

namespace {

namespace fs = std::filesystem;

std::string firstLine(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

// Processes whose command name is "gibench", this one left out.
int countOtherGibench(const fs::path& proc) {
  std::error_code ec;
  fs::directory_iterator it(proc, ec);
  if (ec) return -1;
  const std::string self = std::to_string(getpid());
  int count = 0;
  for (const fs::directory_entry& entry : it) {
    const std::string pid = entry.path().filename().string();
    if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos || pid == self)
      continue;
    count += firstLine(entry.path() / "comm") == "gibench";
  }
  return count;
}

}  // namespace

ConditionsSample sampleConditions(const fs::path& root) {
  ConditionsSample sample;
  const std::string load = firstLine(root / "proc/loadavg");
  if (!load.empty()) {
    char* end = nullptr;
    const double value = std::strtod(load.c_str(), &end);
    if (end != load.c_str()) sample.load = value;
  }
  sample.governor = firstLine(root / "sys/devices/system/cpu/cpu0/cpufreq/scaling_governor");
  sample.other_gibench = countOtherGibench(root / "proc");
  return sample;
}

results::RunConditions conditionsBetween(const ConditionsSample& before,
                                         const ConditionsSample& after) {
  results::RunConditions conditions;
  conditions.load_before = before.load;
  conditions.load_after = after.load;
  conditions.governor = before.governor;
  conditions.other_gibench = before.other_gibench;
  return conditions;
}

}  // namespace gib::suites
