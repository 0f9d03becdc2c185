// One job of a run: render (or fetch from the reference store), measure against the reference of
// the job's path class and against the full reference, time, and write the job's images (into
// the files suites/job_directory.h names; the pictures for the report: suites/job_images.h).
#pragma once

#include "common/parameters.h"
#include "metrics/pass_timing_summary.h"
#include "realtime/gl/context.h"
#include "realtime/technique.h"
#include "reference/reference_store.h"
#include "results/results.h"
#include "scene/scene.h"
#include "suites/job_directory.h"
#include "suites/job_expansion.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace gib::suites {

// A job checked and ready to run: everything that can be wrong with its input is found here,
// before the run writes anything.
struct PreparedJob {
  const Job* job = nullptr;
  scene::Scene scene;
  int width = 0, height = 0;
  const rt::TechniqueInfo* technique = nullptr;  // null for a reference job
  std::optional<ParameterValues> parameters;     // of the technique
  scene::PathClass path_class;                   // of the technique; every path for the reference
  // What the technique's image is when it is not radiance (rt::Technique::imageObscurance): the
  // job is then measured against a reference of this obscurance alone.
  std::optional<scene::ObscuranceDefinition> obscurance;
  std::string scene_hash;  // scene::hashScene, computed once
  std::string hash;        // what makes a recorded result of this job still valid (resume)
};

// Loads the scene, parses the parameters, checks that checkpoints go with an iterative technique.
// Throws gib::InputError naming the job.
PreparedJob prepareJob(const Job& job);

struct JobEnvironment {
  ref::ReferenceStore* store = nullptr;
  rt::gl::ContextOptions gl;
  bool progress = false;  // progress bars on a terminal
  // Called with short notes of what the job is doing ("reference: rendering 128x128 at 1024 spp").
  std::function<void(const std::string&)> note;
};

// What defines the job (id, scene, technique, parameters, size, class, hash), before any of it
// runs: the start of its result, and all of a failed job's.
results::JobResult describeJob(const PreparedJob& job);

// Runs the job and writes its files into `files` (an empty job directory; the results record
// their paths relative to its run directory). The GL identity of a technique job is returned
// through `gl` when given.
results::JobResult executeJob(const PreparedJob& job, const JobEnvironment& environment,
                              const JobDirectory& files, rt::gl::GlIdentity* gl = nullptr);

// The store specs of the references the job is measured against: its class's, then the full
// one when that differs (a reference job: its class's alone; a job whose image is an obscurance:
// that obscurance's alone).
std::vector<ref::ReferenceSpec> jobReferences(const PreparedJob& job);

// Fetches the job's references, rendering what the store lacks, and nothing else: what a Slurm
// CPU task does for a technique job before its GPU task runs (suites/slurm_submission.h).
void obtainJobReferences(const PreparedJob& job, const JobEnvironment& environment);

// One more run of a technique job (`repeats` > 1): a fresh GL context and the job's frames, its
// timings alone (the images and metrics of the first run stand: renders are deterministic).
metrics::PassTimings repeatTechniqueJob(const PreparedJob& job, const JobEnvironment& environment);

}  // namespace gib::suites
