// gibench: the command line of GI Bench (docs/architecture.md, "Command line").
// Exit codes: 0 success, 1 a regression found (diff), 2 bad input, 3 an internal failure, 4 a
// timing `diff --confirm` could not confirm (nothing regressed).
#include "cli/commands.h"
#include "common/environment_error.h"
#include "common/input_error.h"
#include "gib/version.h"

#include <fmt/format.h>

#include <cstdio>
#include <exception>
#include <map>
#include <string>

int main(int argc, char** argv) {
  CLI::App app{"gibench: validation and benchmark harness for real-time global illumination",
               "gibench"};
  app.set_version_flag("--version", std::string(gib::kVersion));
  app.require_subcommand(1);
  std::map<CLI::App*, gib::cli::CommandRunner> runners;
  auto add = [&](gib::cli::CommandRunner (*adder)(CLI::App&), const char* name) {
    gib::cli::CommandRunner runner = adder(app);
    runners[app.get_subcommand(name)] = std::move(runner);
  };
  add(&gib::cli::addListCommand, "list");
  add(&gib::cli::addRenderCommand, "render");
  add(&gib::cli::addCompareCommand, "compare");
  add(&gib::cli::addRunCommand, "run");
  add(&gib::cli::addDiffCommand, "diff");
  add(&gib::cli::addHistoryCommand, "history");
  add(&gib::cli::addStoreCommand, "store");
  add(&gib::cli::addReportCommand, "report");
  add(&gib::cli::addExportBlenderCommand, "export-blender");
  add(&gib::cli::addMergeCommand, "merge");
  add(&gib::cli::addSolidAngleBenchCommand, "solid-angle-bench");
  add(&gib::cli::addRaycastBenchCommand, "raycast-bench");
  add(&gib::cli::addSkyCommand, "sky");

  // CLI11 reports a mistyped command as "A subcommand is required", which does not name it.
  if (argc > 1 && argv[1][0] != '-') {
    std::string known;
    bool found = false;
    for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
      known += (known.empty() ? "" : ", ") + sub->get_name();
      found = found || sub->get_name() == argv[1];
    }
    if (!found) {
      fmt::print(stderr,
                 "gibench: unknown command '{}'; the commands are {} (see `gibench --help`)\n",
                 argv[1], known);
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // One line naming the problem and where to look, exit code 2 (docs/architecture.md, "Errors").
    fmt::print(stderr, "gibench: {}; see `gibench --help`\n", e.what());
    return 2;
  }

  try {
    for (CLI::App* sub : app.get_subcommands()) return runners.at(sub)();
    return 2;
  } catch (const gib::InputError& e) {
    fmt::print(stderr, "gibench: {}\n", e.what());
    return 2;
  } catch (const gib::EnvironmentError& e) {
    // The input is fine; this machine cannot do it (a GL driver's failure): exit code 1.
    fmt::print(stderr, "gibench: {}\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "gibench: internal error: {}\n", e.what());
    return 3;
  }
}
