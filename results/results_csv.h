// results.csv: one row per job for spreadsheets and scripts (RFC 4180: comma-separated, fields
// with commas, quotes or line breaks quoted, CRLF line ends). The full record is results.json.
#pragma once

#include "results/results.h"

#include <string>

namespace gib::results {

// Columns: run_id, git_commit, job, case, scene, technique, parameters ("k=v;k=v"),
// scene_parameters, width, height, path_class, reference_key, spp, then one column per metric
// value (the union over the jobs, in first-seen order; empty where a job lacks it), the
// full-reference values as full_<name>, then frame_median_ms (empty when not timed), upload_ms,
// prepare_ms, seconds. Non-finite numbers are "nan", "inf", "-inf".
std::string resultsCsv(const RunResults& results);

}  // namespace gib::results
