#include "suites/run_directory.h"

#include "common/input_error.h"
#include "image/output_files.h"
#include "results/results_json.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <cerrno>
#include <cstring>
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

// Empty but for another process's state file being staged (publishStateOnce): a new run's
// directory, which that process is about to claim.
bool isEmptyDirectory(const fs::path& dir) {
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.front() != '.' || name.find(kStateFile) == std::string::npos) return false;
  }
  return !ec;
}

}  // namespace

namespace {

RunState parseState(const fs::path& dir) {
  const fs::path state = dir / kStateFile;
  std::ifstream in(state);
  const nlohmann::json json = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  auto isString = [&](const char* key) { return json.contains(key) && json[key].is_string(); };
  if (!json.is_object() || !isString("run_id") || !isString("suite") || !isString("started"))
    throw InputError(
        fmt::format("'{}' is damaged; remove the run directory '{}' or choose "
                    "another --out",
                    state.string(), dir.string()));
  RunState parsed;
  parsed.run_id = json["run_id"];
  parsed.suite = json["suite"];
  parsed.started = json["started"];
  // Added with sharding and Slurm: runs started before them lack these.
  if (isString("suite_file")) parsed.suite_file = json["suite_file"].get<std::string>();
  if (json.contains("only") && json["only"].is_array())
    for (const nlohmann::json& pattern : json["only"])
      if (pattern.is_string()) parsed.only.push_back(pattern);
  return parsed;
}

// Publishes the state file only if none exists: written beside it, then hard-linked into place
// (link fails when the name exists, atomically, on local filesystems and NFS alike). False when
// another process published first.
bool publishStateOnce(const fs::path& dir, const RunState& state) {
  const nlohmann::ordered_json json = {{"run_id", state.run_id},
                                       {"suite", state.suite},
                                       {"suite_file", state.suite_file.string()},
                                       {"only", state.only},
                                       {"started", state.started}};
  const fs::path staged = dir / fmt::format(".{}.{}", kStateFile, getpid());
  image::writeTextFile(staged, json.dump(2) + "\n");
  const int linked = link(staged.c_str(), (dir / kStateFile).c_str());
  const int error = errno;
  std::error_code ignored;
  fs::remove(staged, ignored);
  if (linked == 0) return true;
  if (error == EEXIST) return false;
  throw InputError(fmt::format("cannot write '{}' ({}); choose another --out",
                               (dir / kStateFile).string(), std::strerror(error)));
}

}  // namespace

RunState RunDirectory::readState(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_regular_file(dir / kStateFile, ec))
    throw InputError(fmt::format("'{}' holds no gibench run (no {}); give a run directory",
                                 dir.string(), kStateFile));
  return parseState(dir);
}

RunDirectory RunDirectory::open(const fs::path& dir, const RunState& fresh) {
  RunDirectory run;
  run.dir_ = dir;
  std::error_code ec;
  if (!fs::is_regular_file(dir / kStateFile, ec)) {
    if (fs::exists(dir, ec) && fs::is_directory(dir, ec) && !isEmptyDirectory(dir))
      throw InputError(
          fmt::format("'{}' is not empty and holds no gibench run; choose another --out "
                      "(or an empty or new directory)",
                      dir.string()));
    createDirectory(dir);
    if (publishStateOnce(dir, fresh)) {
      run.state_ = fresh;
      return run;
    }
  }
  run.state_ = parseState(dir);
  if (run.state_.suite != fresh.suite)
    throw InputError(fmt::format("'{}' holds a run of suite '{}', not '{}'; choose another --out",
                                 dir.string(), run.state_.suite, fresh.suite));
  run.resumed_ = true;
  return run;
}

JobDirectory RunDirectory::jobDirectory(const Job& job) const {
  return JobDirectory(dir_, job.slug);
}

std::optional<results::JobResult> RunDirectory::finishedJob(const Job& job,
                                                            const std::string& job_hash) const {
  const fs::path file = jobDirectory(job).result_json;
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

JobDirectory RunDirectory::prepareJob(const Job& job) const {
  const JobDirectory files = jobDirectory(job);
  std::error_code ec;
  fs::remove_all(files.dir, ec);
  if (ec)
    throw InputError(
        fmt::format("cannot clear '{}' ({}); remove it by hand", files.dir.string(), ec.message()));
  createDirectory(files.dir);
  return files;
}

void RunDirectory::recordJob(const Job& job, const results::JobResult& result) const {
  results::writeJobFile(jobDirectory(job).result_json, result);
}

void RunDirectory::recordFailure(const Job& job, const std::string& job_hash,
                                 const std::string& error) const {
  const JobDirectory files = jobDirectory(job);
  std::error_code ec;
  fs::create_directories(files.dir, ec);
  const nlohmann::ordered_json json = {{"id", job.id}, {"job_hash", job_hash}, {"error", error}};
  image::writeTextFile(files.failed_json, json.dump(2) + "\n");
}

std::optional<std::string> RunDirectory::failure(const Job& job,
                                                 const std::string& job_hash) const {
  std::ifstream in(jobDirectory(job).failed_json);
  if (!in) return std::nullopt;
  const nlohmann::json json = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (!json.is_object() || json.value("id", "") != job.id ||
      json.value("job_hash", "") != job_hash || !json.contains("error") ||
      !json["error"].is_string())
    return std::nullopt;
  return json["error"].get<std::string>();
}

}  // namespace gib::suites
