#include "cli/commands.h"
#include "common/input_error.h"
#include "common/join.h"
#include "metrics/metric_registry.h"
#include "realtime/technique.h"
#include "scene/builtin_scenes.h"
#include "scene/path_class.h"
#include "suites/job_expansion.h"
#include "suites/suite_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <vector>

namespace gib::cli {

namespace {

// The suites shipped with the source: suites/*.toml, then the figure suites.
void listSuites() {
  namespace fs = std::filesystem;
  const fs::path root(GIB_SUITES_DIR);
  std::vector<fs::path> files;
  for (const fs::path& dir : {root, root / "figures"}) {
    std::error_code ec;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec))
      if (entry.path().extension() == ".toml") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    const suites::Suite suite = suites::loadSuiteFile(file);
    fmt::print("{:<36} {:>4} jobs  {}\n", file.lexically_relative(root.parent_path()).string(),
               suites::expandSuite(suite).size(), suite.description);
  }
}

// The path class of the technique's defaults; for one whose iterations add bounces, the class
// after none and after one. Constructing a technique does no GL work (that is prepare's), so the
// list needs no context to say which paths it models.
std::string defaultPathClass(const rt::TechniqueInfo& info) {
  const ParameterValues defaults = parseParameters(info.parameters, {}, info.name);
  const std::unique_ptr<rt::Technique> technique = info.create(defaults);
  const scene::PathClass none = technique->pathClassAfter(0), one = technique->pathClassAfter(1);
  if (!technique->iterative() || none == one) return scene::describePathClass(none);
  return fmt::format("{} after 0 iterations, {} after 1 (one more bounce per iteration)",
                     scene::describePathClass(none), scene::describePathClass(one));
}

// What the technique's README (realtime/techniques/<name>/README.md) shows between its
// "generated" markers: the catalogue's own words, parameter table and declared passes.
// "participating medium (scenes that have one: cloud), ray caster".
std::string needsText(const rt::TechniqueInfo& info) {
  return joinNames(info.needs, ", ",
                   [](rt::TechniqueNeed need) { return std::string(rt::needName(need)); });
}

// What it renders where a scene has it, beyond Lambert and Phong surfaces and the scene's lights
// (TechniqueInfo::renders_*): "mirrors and glass, environment maps", or empty.
std::string rendersText(const rt::TechniqueInfo& info) {
  std::vector<std::string> parts;
  if (info.rendersSpecularMaterials()) parts.emplace_back("mirrors and glass");
  if (info.renders_environment_map) parts.emplace_back("environment maps");
  return joinNames(parts, ", ");
}

std::string techniqueMarkdown(const rt::TechniqueInfo& info) {
  std::string out = fmt::format(
      "`{}`: {}.\n\nSource: {}. Path class with the defaults: {}.\n\n## Parameters "
      "(`--set key=value`)\n\n{}\n## Passes\n\n| pass | what it times |\n|---|---|\n",
      info.name, info.description, info.source, defaultPathClass(info),
      parameterMarkdownTable(info.parameters));
  for (const rt::DeclaredPass& pass : info.passes.passes())
    out += fmt::format("| `{}` | {} |\n", pass.path, pass.description);
  if (!info.needs.empty()) out += fmt::format("\n## Needs\n\n{}\n", needsText(info));
  if (const std::string renders = rendersText(info); !renders.empty())
    out += fmt::format("\n## Renders, where a scene has them\n\n{}\n", renders);
  auto outputs = [&](std::string_view title, std::string_view prefix,
                     const std::vector<rt::DeclaredOutput>& declared) {
    if (declared.empty()) return;
    out += fmt::format("\n## {}\n\n| name | what it shows |\n|---|---|\n", title);
    for (const rt::DeclaredOutput& output : declared)
      out += fmt::format("| `{}{}` | {} |\n", prefix, output.name, output.description);
  };
  outputs("Auxiliary images (`image = \"aux:<name>\"` in a figure)", "aux:", info.auxiliary_images);
  outputs("Statistics (quantities of a chart or paper value)", "statistic:", info.statistics);
  return out;
}

void listTechniques() {
  std::size_t width = std::string_view("reference").size();
  for (const rt::TechniqueInfo& info : rt::techniqueCatalogue())
    width = std::max(width, info.name.size());
  fmt::print("{:<{}} {}\n", "reference", width,
             "Embree path tracer (ground truth); options: --spp --seed --paths --min-bounces "
             "--max-bounces --checkpoints --threads");
  for (const rt::TechniqueInfo& info : rt::techniqueCatalogue()) {
    fmt::print("{:<{}} {}\n", info.name, width, info.description);
    fmt::print("{:<{}}   source: {}\n", "", width, info.source);
    fmt::print("{:<{}}   path class (defaults): {}\n", "", width, defaultPathClass(info));
    if (!info.needs.empty()) fmt::print("{:<{}}   needs: {}\n", "", width, needsText(info));
    if (const std::string renders = rendersText(info); !renders.empty())
      fmt::print("{:<{}}   renders: {}\n", "", width, renders);
    for (const std::string& line : describeParameters(info.parameters))
      fmt::print("{:<{}}   --set {}\n", "", width, line);
    std::vector<std::string> passes;
    for (const rt::DeclaredPass& pass : info.passes.passes()) passes.push_back(pass.path);
    fmt::print("{:<{}}   passes: {}\n", "", width, joinNames(passes, ", "));
    auto names = [](const std::vector<rt::DeclaredOutput>& declared) {
      return joinNames(declared, ", ", [](const rt::DeclaredOutput& o) { return o.name; });
    };
    if (!info.auxiliary_images.empty())
      fmt::print("{:<{}}   auxiliary images: {}\n", "", width, names(info.auxiliary_images));
    if (!info.statistics.empty())
      fmt::print("{:<{}}   statistics: {}\n", "", width, names(info.statistics));
  }
}

}  // namespace

CommandRunner addListCommand(CLI::App& app) {
  CLI::App* list = app.add_subcommand("list", "List scenes, techniques, metrics or suites");
  auto what = std::make_shared<std::string>();
  auto names = std::make_shared<std::vector<std::string>>();
  auto markdown = std::make_shared<bool>(false);
  list->add_option("what", *what, "scenes | techniques | metrics | suites")->required();
  list->add_option("names", *names, "techniques: only these (with --markdown)");
  list->add_flag("--markdown", *markdown,
                 "techniques: each one's documentation as Markdown (the generated part of "
                 "realtime/techniques/<name>/README.md)");
  return [what, names, markdown] {
    if ((*markdown || !names->empty()) && *what != "techniques")
      throw InputError(fmt::format(
          "names and --markdown apply to `gibench list techniques`, not to '{}'", *what));
    if (*what == "techniques" && *markdown) {
      std::vector<const rt::TechniqueInfo*> chosen;
      for (const std::string& name : *names) chosen.push_back(&rt::findTechnique(name));
      if (names->empty())
        for (const rt::TechniqueInfo& info : rt::techniqueCatalogue()) chosen.push_back(&info);
      for (std::size_t i = 0; i < chosen.size(); ++i)
        fmt::print("{}{}", i ? "\n" : "", techniqueMarkdown(*chosen[i]));
      return 0;
    }
    if (!names->empty())
      throw InputError(
          "technique names go with --markdown: `gibench list techniques --markdown "
          "direct`");
    if (*what == "scenes") {
      for (const scene::BuiltinSceneInfo& info : scene::builtinScenes()) {
        fmt::print("{:<10} {}\n", info.name, info.description);
        for (const std::string& line : describeParameters(info.parameters))
          fmt::print("{:<10}   --scene-set {}\n", "", line);
      }
      fmt::print("{:<10} {}\n", "FILE.toml", "a scene file (TOML referencing OBJ meshes)");
      return 0;
    }
    if (*what == "techniques") {
      listTechniques();
      return 0;
    }
    if (*what == "metrics") {
      for (const metrics::MetricInfo& info : metrics::metricCatalogue())
        fmt::print("{:<10} {}\n", info.name, info.description);
      return 0;
    }
    if (*what == "suites") {
      listSuites();
      return 0;
    }
    throw InputError(
        fmt::format("cannot list '{}'; choose scenes, techniques, metrics or suites", *what));
  };
}

}  // namespace gib::cli
