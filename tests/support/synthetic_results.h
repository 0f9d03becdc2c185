// Synthetic run results for the tests of results files, the diff, the history database and the
// commands that read them: no rendering, every field chosen by the test.
#pragma once

#include "results/results.h"

#include <cstdint>
#include <string>
#include <vector>

namespace gib::test {

// Per-frame times around `median_ms` with a realistic spread: a log-normal body of relative
// spread `relative_noise` and an occasional slow frame (one in eight, 5-20% slower), as on a
// shared machine. Deterministic for a seed.
std::vector<double> noisyFrameTimes(std::uint64_t seed, int frames, double median_ms,
                                    double relative_noise = 0.03);

// A technique job on cornell with the given metric values and, when given, frame samples.
results::JobResult syntheticJob(const std::string& id, const results::NamedValues& metrics,
                                const std::vector<double>& frame_samples_ms = {});

// A run of `jobs` with plain metadata.
results::RunResults syntheticRun(const std::string& id, std::vector<results::JobResult> jobs);

// A run with every optional part present (full reference, convergence, timings, paper values,
// charts, a figure, per-metric tolerances, infinite values) beside a reference job where they are
// absent. No NaN, so that operator== can compare a round trip.
results::RunResults richResults();

}  // namespace gib::test
