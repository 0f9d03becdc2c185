// The parts of a suite file that are about judging and presenting results rather than rendering:
// [tolerances] (how much may change before `gibench diff` calls it a regression) and [[paper]]
// (the source document's numbers, shown beside ours in a figure suite's report).
//
//   [tolerances]
//   default = { relative = 0.05 }                 # every metric value without its own entry
//   relmse = { absolute = 1e-4, relative = 0.1 }  # a metric value name (relmse, flip_mean, …)
//   frame_time = { relative = 0.1, significance = 0.01 }
//
//   [[paper]]
//   job = "cornell-direct/shadow=pcf"   # a job id of this suite
//   quantity = "frame"                  # a metric value name or a timing pass name
//   value = 12.5
//   unit = "ms"                         # optional
//   source = "Nijasure et al. 2005, Table 1"
//   note = "Radeon 9800 Pro"            # optional
//   tolerance = 0.05                    # optional, relative: ours reproduces the value when
//                                       # |ours − value| ≤ 0.05·|value|; finite, ≥ 0. Left out
//                                       # for numbers only shown (times from other hardware)
#pragma once

#include "common/toml_reader.h"
#include "results/results.h"
#include "suites/job_expansion.h"

#include <vector>

namespace gib::suites {

results::Tolerances readTolerances(const TomlTableReader& root, const toml::node& node);

// [[chart]]: a figure of the suite's jobs (results::ChartSpec). Checks the quantities' syntax,
// that the jobs glob matches a job, and that every pass a quantity names is declared by every
// technique among those jobs (realtime/pass_declarations.h).
//
//   [[chart]]
//   title = "Fig. 7: time per iteration against vertex count"
//   jobs = "cornell-stochastic_radiosity/*"   # optional glob over job ids (default: all)
//   x = "statistic:vertices"
//   y = "iteration"
//   series = "parameter:selection"            # optional: one line per value
//   log_x = true                              # optional, default false; log_y likewise
//   front = false                             # optional: mark the Pareto front
std::vector<results::ChartSpec> readCharts(const TomlTableReader& root,
                                           const std::vector<Job>& jobs);

// Checks that every entry names a job of `jobs`, and that a pass its quantity names is declared
// by the job's technique.
std::vector<results::PaperValue> readPaperValues(const TomlTableReader& root,
                                                 const std::vector<Job>& jobs);

// Checks a quantity of `job` (results/quantity.h): its syntax, and that every pass it names is
// declared by the job's technique. `what` names it in the message ("figure 'fig6', panel 2's
// metric").
void checkQuantity(const TomlErrorReporter& errors, const toml::node& node, std::string_view what,
                   const std::string& quantity, const Job& job);

}  // namespace gib::suites
