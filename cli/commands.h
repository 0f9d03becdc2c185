// The subcommands of gibench. Each registers its options on the app and returns the function
// that runs it; the command line stays thin: it parses, calls the layers, prints.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace gib::cli {

using CommandRunner = std::function<int()>;

CommandRunner addListCommand(CLI::App& app);
CommandRunner addRenderCommand(CLI::App& app);
CommandRunner addCompareCommand(CLI::App& app);
CommandRunner addRunCommand(CLI::App& app);
CommandRunner addDiffCommand(CLI::App& app);
CommandRunner addHistoryCommand(CLI::App& app);
CommandRunner addStoreCommand(CLI::App& app);
CommandRunner addReportCommand(CLI::App& app);
CommandRunner addExportBlenderCommand(CLI::App& app);
CommandRunner addMergeCommand(CLI::App& app);
CommandRunner addSolidAngleBenchCommand(CLI::App& app);
CommandRunner addRaycastBenchCommand(CLI::App& app);
CommandRunner addSkyCommand(CLI::App& app);

}  // namespace gib::cli
