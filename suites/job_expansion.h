// Expanding a suite into jobs: one job per case and combination of its sweeps. A job is
// everything one render-and-measure step needs, with a stable id that names it in results,
// history and diffs.
#pragma once

#include "suites/suite.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gib::suites {

// Canonical key=value pairs, in the order of the suite file.
using Assignments = std::vector<std::pair<std::string, std::string>>;

struct Job {
  std::string suite;
  std::string case_name;
  // "<case>" when the case sweeps nothing, else "<case>/<key>=<value>,…" over its swept keys
  // (scene parameters as "scene.<key>") in file order: "cornell-direct/shadow=pcf,light_samples=4".
  // Fixed values are part of the case, not of the id. Values are canonical, so the id does not
  // depend on how a number is written.
  std::string id;
  // The id made safe for a file name (letters, digits, '.', '_', '-'; at most 120 characters):
  // "cornell-direct__shadow-pcf__light_samples-4". Unique within the suite (a short hash of the
  // id is appended where two would collide or the name is too long).
  std::string slug;

  SceneSpec scene;
  Assignments scene_parameters;      // every key of the case's scene_set, this job's values
  std::string technique;             // a catalogue name or kReferenceTechnique
  Assignments technique_parameters;  // every key of the case's set, this job's values

  RunSettings settings;

  bool isReference() const { return technique == kReferenceTechnique; }
};

// "key=value" strings, as scene::loadScene and parseParameters take them.
std::vector<std::string> assignmentStrings(const Assignments& assignments);

// One job per case × combination of its sweeps: cases in file order; within a case, the
// scene_set sweeps, then the set sweeps, each in file order, the last key varying fastest.
std::vector<Job> expandSuite(const Suite& suite);

}  // namespace gib::suites
