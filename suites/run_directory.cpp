#include "suites/run_directory.h"

#include "common/input_error.h"
#include "image/output_files.h"
#include "results/results_json.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <fstream>

namespace gib::suites {

namespace {

namespace fs = std::filesystem;

constexpr const char* kStateFile = "run-state.json";

// Creates `dir` (and its parents); an InputError naming --out when that is impossible.
void createDirectory(const fs::path& dir) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw InputError(
        fmt::format("--out '{}' is a file; give a directory for the run", dir.string()));
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw InputError(fmt::format("cannot create the run directory '{}' ({}); choose another --out",
                                 dir.string(), ec ? ec.message() : "not a directory"));
}

bool isEmptyDirectory(const fs::path& dir) {
  std::error_code ec;
  return fs::is_empty(dir, ec) && !ec;
}

}  // namespace

RunDirectory RunDirectory::open(const fs::path& dir, const std::string& suite,
                                const results::RunInfo& fresh) {
  RunDirectory run;
  run.dir_ = dir;
  const fs::path state = dir / kStateFile;
  std::error_code ec;
  if (fs::is_regular_file(state, ec)) {
    std::ifstream in(state);
    const nlohmann::json json = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (!json.is_object() || !json.contains("run_id") || !json.contains("suite") ||
        !json.contains("started") || !json["run_id"].is_string() || !json["suite"].is_string() ||
        !json["started"].is_string())
      throw InputError(
          fmt::format("'{}' is damaged; remove the run directory '{}' or choose "
                      "another --out",
                      state.string(), dir.string()));
    if (json["suite"] != suite)
      throw InputError(fmt::format("'{}' holds a run of suite '{}', not '{}'; choose another --out",
                                   dir.string(), json["suite"].get<std::string>(), suite));
    run.run_id_ = json["run_id"];
    run.started_ = json["started"];
    run.resumed_ = true;
    return run;
  }
  if (fs::exists(dir, ec) && fs::is_directory(dir, ec) && !isEmptyDirectory(dir))
    throw InputError(
        fmt::format("'{}' is not empty and holds no gibench run; choose another --out "
                    "(or an empty or new directory)",
                    dir.string()));
  createDirectory(dir);
  run.run_id_ = fresh.id;
  run.started_ = fresh.started;
  const nlohmann::ordered_json json = {
      {"run_id", run.run_id_}, {"suite", suite}, {"started", run.started_}};
  image::writeTextFile(state, json.dump(2) + "\n");
  return run;
}

fs::path RunDirectory::jobDirectory(const Job& job) const {
  return dir_ / "jobs" / job.slug;
}

std::optional<results::JobResult> RunDirectory::finishedJob(const Job& job,
                                                            const std::string& job_hash) const {
  const fs::path file = jobDirectory(job) / "result.json";
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return std::nullopt;
  try {
    results::JobResult result = results::readJobFile(file);
    if (result.job_hash == job_hash && result.id == job.id) return result;
  } catch (const InputError&) {
    // A result of an older schema or a damaged file: the job runs again.
  }
  return std::nullopt;
}

fs::path RunDirectory::prepareJob(const Job& job) const {
  const fs::path dir = jobDirectory(job);
  std::error_code ec;
  fs::remove_all(dir, ec);
  if (ec)
    throw InputError(
        fmt::format("cannot clear '{}' ({}); remove it by hand", dir.string(), ec.message()));
  createDirectory(dir);
  return dir;
}

void RunDirectory::recordJob(const Job& job, const results::JobResult& result) const {
  results::writeJobFile(jobDirectory(job) / "result.json", result);
}

}  // namespace gib::suites
