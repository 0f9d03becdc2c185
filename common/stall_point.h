// Points in the writes a run makes where a fault test can hold the process, so that a kill lands
// inside the write rather than wherever a random instant falls (docs/reliability.md, "Faults":
// the writes of results, history and report take milliseconds of a run, and random kills missed
// them). The environment variable GIB_STALL_AT holds a shell pattern (fnmatch); at every point
// whose name it matches, the process prints "gibench: stalled at <name>" on stderr and sleeps
// GIB_STALL_MS milliseconds (default 60000) before going on. Unset or empty: no stall, and a
// point costs one getenv. The points:
//   write:<file name>   an atomic write, its temporary file complete, before the rename into place
//                       (results.json, results.csv, index.html, a job page, an EXR, timings.json…)
//   store-entry         a reference-store entry staged whole, before its directory is renamed in
//   history-commit      a run's rows inserted in the history database, before the commit
#pragma once

#include <string>

namespace gib {

void stallPoint(const std::string& name);

}  // namespace gib
