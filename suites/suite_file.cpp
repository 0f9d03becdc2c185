#include "suites/suite_file.h"

#include "suites/job_expansion.h"
#include "suites/suite_annotations.h"
#include "suites/suite_figures.h"

#include "common/input_error.h"
#include "common/join.h"
#include "common/parameters.h"
#include "common/toml_reader.h"
#include "metrics/metric_registry.h"
#include "realtime/technique.h"
#include "scene/builtin_scenes.h"
#include "scene/path_class.h"
#include "scene/path_expression.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace gib::suites {

namespace {

namespace fs = std::filesystem;

constexpr long long kMaxImageSide = 32768;      // as scene files
constexpr long long kMaxFrames = 1000000;       // frames, warm-up frames
constexpr long long kMaxSpp = 1LL << 30;        // reference samples per pixel
constexpr long long kMaxBounces = 1000000;      // beyond this, write "unlimited"
constexpr std::size_t kMaxJobsPerCase = 10000;  // a sweep beyond this is surely a mistake

// Enough for any convergence study; a typo of 10^7 would run for days.
constexpr long long kMaxIterations = 100000;
// Whole runs of one technique job; more belong in a benchmark than in a suite.
constexpr long long kMaxRepeats = 100;

const std::vector<std::string> kSettingKeys = {"width",  "height",  "metrics",   "frames",
                                               "warmup", "repeats", "reference", "lens"};
const std::vector<std::string> kReferenceKeys = {
    "spp",   "seed",           "min_bounces",          "max_bounces",
    "paths", "pixel_sampling", "environment_occlusion"};

bool isSafeName(std::string_view name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-';
  });
}

std::string safeName(std::string name) {
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-') c = '_';
  return name;
}

std::vector<std::string> withKeys(std::vector<std::string> keys,
                                  const std::vector<std::string>& more) {
  keys.insert(keys.end(), more.begin(), more.end());
  return keys;
}

// What [defaults] and a case may set, with the nodes that set them for later checks.
struct Settings {
  Settings() { run.metrics = metrics::parseMetricList("all"); }
  RunSettings run;
  const toml::node* width_node = nullptr;
  const toml::node* height_node = nullptr;
  const toml::node* min_bounces_node = nullptr;
  const toml::node* max_bounces_node = nullptr;
  const toml::node* paths_node = nullptr;
};

// The metric names of `metrics = "all"`, "relmse,flip" or ["relmse", "flip"], in catalogue
// order.
std::vector<std::string> readMetrics(const TomlTableReader& t, const toml::node& node) {
  std::vector<const toml::node*> items;
  if (const toml::array* array = node.as_array()) {
    if (array->empty())
      t.errors().fail(node, fmt::format("{} must not be empty", t.path("metrics")),
                      "list metric names (`gibench list metrics`) or write metrics = \"all\"");
    for (const toml::node& item : *array) items.push_back(&item);
  } else {
    items.push_back(&node);
  }
  std::vector<std::string> named;
  for (const toml::node* item : items) {
    const std::string list = t.string(*item, "metrics");
    try {
      for (std::string& name : metrics::parseMetricList(list)) named.push_back(std::move(name));
    } catch (const InputError& e) {
      t.errors().failWith(item->source(), e.what());
    }
  }
  std::vector<std::string> ordered;
  for (const metrics::MetricInfo& info : metrics::metricCatalogue())
    if (std::find(named.begin(), named.end(), info.name) != named.end())
      ordered.push_back(info.name);
  return ordered;
}

void readReference(const TomlTableReader& parent, const toml::node& node, Settings& s) {
  const std::string name = parent.path("reference");
  const TomlTableReader t(parent.errors(),
                          requireTomlTable(parent.errors(), node, name,
                                           fmt::format("write [{}] with spp, seed, min_bounces, "
                                                       "max_bounces, paths, pixel_sampling or "
                                                       "environment_occlusion",
                                                       name)),
                          name, fmt::format("[{}]", name), kReferenceKeys);
  if (const toml::node* n = t.find("spp"))
    s.run.reference.spp = static_cast<int>(t.integer(*n, "spp", 1, kMaxSpp, "1024"));
  if (const toml::node* n = t.find("seed"))
    s.run.reference.seed = static_cast<unsigned long long>(
        t.integer(*n, "seed", 0, std::numeric_limits<long long>::max(), "0"));
  if (const toml::node* n = t.find("min_bounces")) {
    s.run.reference.min_bounces =
        static_cast<int>(t.integer(*n, "min_bounces", 0, kMaxBounces, "0"));
    s.min_bounces_node = n;
  }
  if (const toml::node* n = t.find("max_bounces")) {
    if (const auto* text = n->as_string(); text && text->get() == "unlimited") {
      s.run.reference.max_bounces = scene::PathClass::kUnlimited;
    } else if (!n->is_integer() || n->as_integer()->get() < 0 ||
               n->as_integer()->get() > kMaxBounces) {
      t.errors().fail(*n,
                      fmt::format("{} must be an integer in [0, {}] or \"unlimited\"",
                                  t.path("max_bounces"), kMaxBounces),
                      "write e.g. max_bounces = 1, or max_bounces = \"unlimited\" for every path");
    } else {
      s.run.reference.max_bounces = static_cast<int>(n->as_integer()->get());
    }
    s.max_bounces_node = n;
  }
  if (const toml::node* n = t.find("paths")) {
    const std::string text = t.string(*n, "paths");
    try {
      s.run.reference.paths = scene::PathExpression::parse(text).text();
    } catch (const InputError& e) {
      t.errors().failWith(n->source(), fmt::format("{}: {}", t.path("paths"), e.what()));
    }
    s.paths_node = n;
  }
  if (const toml::node* n = t.find("pixel_sampling")) {
    const std::string sampling = t.string(*n, "pixel_sampling");
    if (sampling != "center" && sampling != "area")
      t.errors().fail(
          *n, fmt::format("{} is '{}', not a pixel sampling", t.path("pixel_sampling"), sampling),
          "write pixel_sampling = \"center\" (camera rays through pixel centres, as "
          "the rasteriser samples) or \"area\" (a box filter over each pixel)");
    s.run.reference.pixel_sampling = sampling;
  }
  if (const toml::node* n = t.find("environment_occlusion"))
    s.run.reference.environment_occlusion = t.boolean(*n, "environment_occlusion");
}

// `lens = { radius = R, focus_distance = D }`: the thin lens over the scene's camera.
void readLens(const TomlTableReader& parent, const toml::node& node, Settings& s) {
  const std::string name = parent.path("lens");
  const TomlTableReader t(
      parent.errors(),
      requireTomlTable(parent.errors(), node, name,
                       "write lens = { radius = 0.05, focus_distance = 4.0 } (scene units)"),
      name, fmt::format("[{}]", name), {"radius", "focus_distance"});
  auto read = [&](std::string_view key, void (*check)(double, std::string_view),
                  std::optional<double>& into) {
    const toml::node* n = t.find(key);
    if (!n) return;
    const double value = t.number(*n, key);
    try {
      check(value, t.path(key));
    } catch (const InputError& e) {
      t.errors().failWith(n->source(), e.what());
    }
    into = value;
  };
  read("radius", scene::checkLensRadius, s.run.lens.radius);
  read("focus_distance", scene::checkFocusDistance, s.run.lens.focus_distance);
}

// Reads the keys of kSettingKeys present in `t` over `s`.
void readSettings(const TomlTableReader& t, Settings& s) {
  if (const toml::node* n = t.find("width")) {
    s.run.width = static_cast<int>(t.integer(*n, "width", 1, kMaxImageSide, "256"));
    s.width_node = n;
  }
  if (const toml::node* n = t.find("height")) {
    s.run.height = static_cast<int>(t.integer(*n, "height", 1, kMaxImageSide, "256"));
    s.height_node = n;
  }
  if (const toml::node* n = t.find("metrics")) s.run.metrics = readMetrics(t, *n);
  if (const toml::node* n = t.find("frames"))
    s.run.frames = static_cast<int>(t.integer(*n, "frames", 1, kMaxFrames, "8"));
  if (const toml::node* n = t.find("warmup"))
    s.run.warmup = static_cast<int>(t.integer(*n, "warmup", 0, kMaxFrames, "2"));
  if (const toml::node* n = t.find("repeats"))
    s.run.repeats = static_cast<int>(t.integer(*n, "repeats", 1, kMaxRepeats, "3"));
  if (const toml::node* n = t.find("reference")) readReference(t, *n, s);
  if (const toml::node* n = t.find("lens")) readLens(t, *n, s);
}

// Checks what only the merged settings of a case can tell.
void checkSettings(const TomlErrorReporter& errors, const Settings& s) {
  if (s.run.width.has_value() != s.run.height.has_value()) {
    const toml::node& given = s.run.width ? *s.width_node : *s.height_node;
    errors.fail(given,
                fmt::format("{} is given without {}", s.run.width ? "width" : "height",
                            s.run.width ? "height" : "width"),
                "give both width and height, or neither for the scene's own size");
  }
  const ReferenceSettings& r = s.run.reference;
  if (r.min_bounces && r.max_bounces && *r.min_bounces > *r.max_bounces)
    errors.fail(*s.min_bounces_node,
                fmt::format("reference min_bounces {} is above max_bounces {}", *r.min_bounces,
                            *r.max_bounces),
                "give min_bounces <= max_bounces");
  if (r.paths && (r.min_bounces || r.max_bounces))
    errors.fail(*s.paths_node,
                fmt::format("reference paths and {} both choose the path class",
                            r.min_bounces ? "min_bounces" : "max_bounces"),
                "give one of them (min_bounces = a with max_bounces = b is paths = "
                "\"L(D|S|P){a,b}E\")");
}

const ParameterSpec* findSpec(const ParameterTable& table, std::string_view key) {
  for (const ParameterSpec& spec : table)
    if (spec.name == key) return &spec;
  return nullptr;
}

bool isVector3(const toml::node& node) {
  const toml::array* array = node.as_array();
  return array && array->size() == 3 &&
         std::all_of(array->begin(), array->end(),
                     [](const toml::node& n) { return std::isfinite(tomlNumber(n)); });
}

// The text of one parameter value as `--set key=value` would give it.
std::string valueText(const TomlErrorReporter& errors, const toml::node& node,
                      const ParameterSpec& spec, const std::string& where) {
  if (const auto* s = node.as_string()) return s->get();
  if (const auto* i = node.as_integer()) return fmt::format("{}", i->get());
  if (const auto* b = node.as_boolean()) return b->get() ? "true" : "false";
  if (node.is_floating_point() && std::isfinite(tomlNumber(node)))
    return fmt::format("{}", tomlNumber(node));
  if (spec.type == ParameterType::kVector3 && isVector3(node)) {
    const toml::array& array = *node.as_array();
    return fmt::format("{},{},{}", tomlNumber(*array.get(0)), tomlNumber(*array.get(1)),
                       tomlNumber(*array.get(2)));
  }
  if (spec.type == ParameterType::kVector3)
    errors.fail(node, fmt::format("{} must be [x, y, z] or \"x,y,z\"", where),
                "write a vector of three finite numbers, or an array of them to sweep");
  errors.fail(node, fmt::format("{} must be a string or a finite number", where),
              "write a value such as \"pcf\" or 4, or an array of them to sweep");
}

// `set` or `scene_set`: each key checked against `table`, each value canonicalised by it.
std::vector<Sweep> readSweeps(const TomlTableReader& t, std::string_view key,
                              const ParameterTable& table, const std::string& owner) {
  const toml::node* node = t.find(key);
  if (!node) return {};
  const TomlErrorReporter& errors = t.errors();
  const std::string name = t.path(key);
  const toml::table& assignments = requireTomlTable(
      errors, *node, name, fmt::format("write {} = {{ key = value, key = [value, value] }}", key));
  std::vector<Sweep> sweeps;
  for (const auto& [key_node, value] : entriesInFileOrder(assignments)) {
    const std::string parameter(key_node->str());
    const ParameterSpec* spec = findSpec(table, parameter);
    if (!spec) {
      const std::string known =
          joinNames(table, ", ", [](const ParameterSpec& s) { return s.name; });
      errors.fail(key_node->source(), fmt::format("{} has no parameter '{}'", owner, parameter),
                  known.empty() ? fmt::format("it takes none; remove {}", name)
                                : fmt::format("its parameters are {}", known));
    }
    const std::string where = fmt::format("{}.{}", name, parameter);
    Sweep sweep;
    sweep.key = parameter;
    std::vector<const toml::node*> items;
    const toml::array* array = value->as_array();
    const bool vector = spec->type == ParameterType::kVector3;
    // [x, y, z] is one vector; an array of numbers of another length is a mistyped one.
    if (vector && array && !isVector3(*value) && !array->empty() &&
        std::all_of(array->begin(), array->end(),
                    [](const toml::node& n) { return n.is_number(); }))
      errors.fail(*value, fmt::format("{} must be [x, y, z] or \"x,y,z\"", where),
                  "write a vector of three finite numbers, or an array of them to sweep");
    if (array && !(vector && isVector3(*value))) {
      if (array->empty())
        errors.fail(*value, fmt::format("{} is an empty sweep", where),
                    "list at least one value, or write a single value");
      sweep.swept = true;
      for (const toml::node& item : *array) items.push_back(&item);
    } else {
      items.push_back(value);
    }
    for (const toml::node* item : items) {
      const std::string text = valueText(errors, *item, *spec, where);
      std::string canonical;
      try {
        canonical = parseParameters(table, {parameter + "=" + text}, owner).text(parameter);
      } catch (const InputError& e) {
        errors.failWith(item->source(), e.what());
      }
      if (std::find(sweep.values.begin(), sweep.values.end(), canonical) != sweep.values.end())
        errors.fail(*item, fmt::format("{} lists the value {} twice", where, canonical),
                    "list each value once");
      sweep.values.push_back(canonical);
    }
    sweeps.push_back(std::move(sweep));
  }
  return sweeps;
}

// The `scene` of a case, with the parameter table of a built-in scene (empty for a file).
SceneSpec readScene(const TomlTableReader& t, const fs::path& base_dir,
                    const ParameterTable** parameters) {
  const toml::node& node = t.require("scene", "\"cornell\"");
  const std::string value = t.string(node, "scene");
  static const ParameterTable kNone;
  *parameters = &kNone;
  for (const scene::BuiltinSceneInfo& info : scene::builtinScenes())
    if (info.name == value) {
      *parameters = &info.parameters;
      return SceneSpec{value, {}};
    }
  const fs::path path(value);
  if (path.extension() != ".toml") {
    const std::string names = joinNames(scene::builtinScenes(), ", ",
                                        [](const scene::BuiltinSceneInfo& s) { return s.name; });
    t.errors().fail(node, fmt::format("unknown scene '{}'", value),
                    fmt::format("use a built-in scene ({}; see `gibench list scenes`) or the path "
                                "of a .toml scene file",
                                names));
  }
  const fs::path file = (base_dir / path).lexically_normal();
  std::error_code ec;
  if (!fs::is_regular_file(file, ec))
    t.errors().fail(node, fmt::format("scene file '{}' not found", file.string()),
                    "check the path (a relative path starts at the suite file's folder)");
  return SceneSpec{path.stem().string(), file};
}

std::vector<int> readCheckpoints(const TomlTableReader& t, const toml::node& node) {
  const toml::array* array = node.as_array();
  const std::string name = t.path("checkpoints");
  if (!array || array->empty())
    t.errors().fail(node, fmt::format("{} must be a non-empty array of integers", name),
                    "write e.g. checkpoints = [1, 4, 16], or leave the key out");
  std::vector<int> checkpoints;
  for (const toml::node& item : *array) {
    const auto* value = item.as_integer();
    if (!value || value->get() < 1 || value->get() > std::numeric_limits<int>::max())
      t.errors().fail(item, fmt::format("{} must hold positive integers", name),
                      "write e.g. checkpoints = [1, 4, 16]");
    if (!checkpoints.empty() && value->get() <= checkpoints.back())
      t.errors().fail(item, fmt::format("{} must be strictly increasing", name),
                      "list each checkpoint once, smallest first");
    checkpoints.push_back(static_cast<int>(value->get()));
  }
  return checkpoints;
}

std::size_t jobCount(const Case& c) {
  std::size_t count = 1;
  for (const auto* sweeps : {&c.scene_parameters, &c.technique_parameters})
    for (const Sweep& sweep : *sweeps) count *= sweep.values.size();
  return count;
}

Case readCase(const TomlErrorReporter& errors, const toml::table& table, std::size_t index,
              const Settings& defaults, const fs::path& base_dir) {
  const TomlTableReader t(
      errors, table, "case", fmt::format("[[case]] entry {}", index + 1),
      withKeys({"name", "scene", "scene_set", "technique", "set", "checkpoints", "iterations"},
               kSettingKeys));
  Case c;
  c.line = static_cast<int>(std::max<toml::source_index>(table.source().begin.line, 1));

  const ParameterTable* scene_table = nullptr;
  c.scene = readScene(t, base_dir, &scene_table);
  if (!c.scene.builtin()) {
    if (const toml::node* n = t.find("scene_set"))
      errors.fail(*n, "a scene file takes no scene_set",
                  "edit the scene file instead, or use a built-in scene");
  }
  c.scene_parameters =
      readSweeps(t, "scene_set", *scene_table, fmt::format("scene '{}'", c.scene.name));

  const toml::node& technique = t.require("technique", "\"direct\"");
  c.technique = t.string(technique, "technique");
  if (c.technique == kReferenceTechnique) {
    if (const toml::node* n = t.find("set"))
      errors.fail(*n, "a reference case takes no set",
                  "give the reference's spp, seed and bounces in [case.reference]");
  } else {
    const rt::TechniqueInfo* info = nullptr;
    try {
      info = &rt::findTechnique(c.technique);
    } catch (const InputError& e) {
      errors.failWith(technique.source(), e.what());
    }
    c.technique_parameters =
        readSweeps(t, "set", info->parameters, fmt::format("technique '{}'", c.technique));
  }

  if (const toml::node* n = t.find("name")) {
    c.name = t.string(*n, "name");
    if (!isSafeName(c.name))
      errors.fail(*n,
                  fmt::format("case name '{}' has characters other than letters, digits, "
                              "'.', '_' and '-'",
                              c.name),
                  "choose a name that can be part of a file name, e.g. \"cornell-direct\"");
  } else {
    c.name = safeName(c.scene.name + "-" + c.technique);
  }

  Settings settings = defaults;
  readSettings(t, settings);
  checkSettings(errors, settings);
  c.settings = settings.run;

  if (const toml::node* n = t.find("checkpoints")) {
    c.settings.checkpoints = readCheckpoints(t, *n);
    if (c.technique == kReferenceTechnique &&
        c.settings.checkpoints.back() > c.settings.reference.spp)
      errors.fail(n->as_array()->back(),
                  fmt::format("checkpoint {} is above the reference's {} spp",
                              c.settings.checkpoints.back(), c.settings.reference.spp),
                  "a reference case's checkpoints are spp counts up to its reference spp");
  }
  if (const toml::node* n = t.find("iterations")) {
    if (c.technique == kReferenceTechnique)
      errors.fail(*n, "a reference case takes no iterations",
                  "give the reference's spp in [case.reference]");
    c.settings.iterations = static_cast<int>(t.integer(*n, "iterations", 0, kMaxIterations, "50"));
    if (!c.settings.checkpoints.empty() && c.settings.checkpoints.back() > *c.settings.iterations)
      errors.fail(*n,
                  fmt::format("iterations = {} is below the last checkpoint, {}",
                              *c.settings.iterations, c.settings.checkpoints.back()),
                  "checkpoints are captured on the way to the job's iterations; raise iterations "
                  "or drop the larger checkpoints");
  }

  if (jobCount(c) > kMaxJobsPerCase)
    errors.fail(table,
                fmt::format("case '{}' expands into {} jobs, more than {}", c.name, jobCount(c),
                            kMaxJobsPerCase),
                "sweep fewer values, or split the case");
  return c;
}

// A case that pairs a technique with a scene that lacks what it needs (a medium, a sky) fails when
// the suite loads, at the case's technique, not when its job runs an hour into the night; so does
// a built-in scene with mirrors or glass (`--scene-set spheres=…`) paired with a technique that
// does not render them. Scene files are loaded only for techniques with such needs (they may be
// large; the runner refuses their mirrors and glass when the job starts), and every scene once per
// technique and parameters.
void checkSceneNeeds(const TomlErrorReporter& errors, const std::vector<const toml::table*>& cases,
                     const Suite& suite, const std::vector<Job>& jobs) {
  std::set<std::string> checked;
  std::map<std::string, scene::Scene> scenes;  // each scene loaded once, whatever the techniques
  for (const Job& job : jobs) {
    if (job.isReference()) continue;
    const rt::TechniqueInfo& info = rt::findTechnique(job.technique);
    if (!needsSceneFeatures(info) && !job.scene.builtin()) continue;
    const std::vector<std::string> parameters = assignmentStrings(job.scene_parameters);
    std::string scene_key = job.scene.nameOrPath();
    for (const std::string& p : parameters) scene_key += '\n' + p;
    if (!checked.insert(job.technique + '\n' + scene_key).second) continue;
    auto loaded = scenes.find(scene_key);
    if (loaded == scenes.end())
      loaded =
          scenes.emplace(scene_key, scene::loadScene(job.scene.nameOrPath(), parameters)).first;
    const std::optional<std::string> missing = rt::missingSceneNeed(info, loaded->second);
    if (!missing) continue;
    for (std::size_t i = 0; i < suite.cases.size(); ++i)
      if (suite.cases[i].name == job.case_name)
        errors.fail(*cases[i]->get("technique"), fmt::format("job '{}': {}", job.id, *missing),
                    "or leave the scene out of this case (`gibench list techniques` says what "
                    "each technique needs)");
  }
}

}  // namespace

Suite loadSuiteFile(const std::filesystem::path& path) {
  const TomlErrorReporter errors(path.string());
  const toml::table document = parseTomlFile(errors, path, "suite file");
  const TomlTableReader root(
      errors, document, "", "the top level of the suite file",
      {"name", "description", "defaults", "case", "tolerances", "paper", "chart", "figure"});

  Suite suite;
  suite.file = fs::absolute(path).lexically_normal();
  const toml::node& name = root.require("name", "\"smoke\"");
  suite.name = root.string(name, "name");
  if (!isSafeName(suite.name))
    errors.fail(name,
                fmt::format("suite name '{}' has characters other than letters, digits, '.', '_' "
                            "and '-'",
                            suite.name),
                "choose a name that can be part of a file name, e.g. \"smoke\"");
  if (const toml::node* n = root.find("description"))
    suite.description = root.string(*n, "description");

  Settings defaults;
  if (const toml::node* n = root.find("defaults")) {
    const TomlTableReader t(errors, requireTomlTable(errors, *n, "defaults", "write [defaults]"),
                            "defaults", "[defaults]", kSettingKeys);
    readSettings(t, defaults);
  }

  const std::vector<const toml::table*> cases = tomlTableArray(root, "case");
  if (cases.empty())
    errors.fail(document, "the suite has no cases",
                "add a [[case]] table with scene and technique");
  const fs::path base_dir = suite.file.parent_path();
  std::map<std::string, int> lines;  // case name -> line of its case
  for (std::size_t i = 0; i < cases.size(); ++i) {
    Case c = readCase(errors, *cases[i], i, defaults, base_dir);
    if (const auto [it, inserted] = lines.emplace(c.name, c.line); !inserted) {
      const toml::node* at = cases[i]->get("name");
      errors.fail(
          at ? at->source() : cases[i]->source(),
          fmt::format("case name '{}' is also the name of the case at line {}", c.name, it->second),
          at ? "give each case its own name"
             : "give the case a name = \"...\" (the default is <scene>-<technique>)");
    }
    suite.cases.push_back(std::move(c));
  }
  if (const toml::node* n = root.find("tolerances")) suite.tolerances = readTolerances(root, *n);
  const std::vector<Job> jobs = expandSuite(suite);
  checkSceneNeeds(errors, cases, suite, jobs);
  suite.paper = readPaperValues(root, jobs);
  suite.charts = readCharts(root, jobs);
  suite.figures = readFigures(root, jobs);
  return suite;
}

}  // namespace gib::suites
