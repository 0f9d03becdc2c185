// What else the machine was doing around a run or a job: the 1-minute load average before and
// after, the CPU frequency governor, other gibench processes. Recorded with the results and shown
// beside the timings, so that a noisy run is visible as such (a load of 3 on two cores, a second
// `gibench run` sharing them, a power-saving governor).
#pragma once

#include "results/results.h"

#include <filesystem>
#include <string>

namespace gib::suites {

struct ConditionsSample {
  double load = -1;        // 1-minute load average; −1 where /proc/loadavg is unreadable
  std::string governor;    // cpu0's scaling governor; empty where cpufreq is not exposed
  int other_gibench = -1;  // gibench processes other than this one; −1 where /proc is unreadable
};

// Reads /proc and /sys under `root` ("/" but in tests).
ConditionsSample sampleConditions(const std::filesystem::path& root = "/");

// The conditions of a span from its two samples: the load before and after, the governor and the
// other processes as seen at the start.
results::RunConditions conditionsBetween(const ConditionsSample& before,
                                         const ConditionsSample& after);

}  // namespace gib::suites
