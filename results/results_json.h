// results.json: reading and writing a run's results (schema: docs/results-schema.md). Writing is
// atomic; reading is strict, so that a truncated or hand-edited file is an error naming the field
// rather than a silently wrong diff.
#pragma once

#include "results/results.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace gib::results {

nlohmann::ordered_json resultsToJson(const RunResults& results);
nlohmann::ordered_json jobToJson(const JobResult& job);
// A job's `timings` (and `iteration_timings`), also written alone as the job's timings.json and
// by `gibench render --timings-json`: clock, frame counts and each pass with its summary and
// per-frame samples.
nlohmann::ordered_json passTimingsToJson(const metrics::PassTimings& timings);
// A timings file of that form (a job's timings.json, `gibench render --timings-json`); throws
// gib::InputError naming the file and the field for a missing or damaged one.
metrics::PassTimings readPassTimingsFile(const std::filesystem::path& path);

// Throw gib::InputError "<source>: <field path>: <problem>; <fix>" for a missing or mistyped
// field, and for a schema name or version this build cannot read. Ordered JSON: metrics and
// parameters keep their order (a nlohmann::json argument converts, but sorts them by name).
RunResults resultsFromJson(const nlohmann::ordered_json& json, const std::string& source);
JobResult jobFromJson(const nlohmann::ordered_json& json, const std::string& source);

// `path` may be a results.json file or a run directory holding one. Throws gib::InputError for a
// missing file or malformed JSON as well.
RunResults readResultsFile(const std::filesystem::path& path);
JobResult readJobFile(const std::filesystem::path& path);

// Atomic (temporary file, then rename); the directory must exist.
void writeResultsFile(const std::filesystem::path& path, const RunResults& results);
void writeJobFile(const std::filesystem::path& path, const JobResult& job);

}  // namespace gib::results
