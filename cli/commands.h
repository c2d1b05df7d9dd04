// The subcommands of rtlab. Each lives in its own file and registers itself on the app.
#pragma once

#include <CLI/CLI.hpp>

namespace rtlab::cli {

void addInfoCommand(CLI::App& app);
void addRenderCommand(CLI::App& app);
void addHitsCommand(CLI::App& app);
void addSceneCommand(CLI::App& app);
void addGradeCommand(CLI::App& app);
void addExportPovCommand(CLI::App& app);
void addExportBlenderCommand(CLI::App& app);
void addRefsCommand(CLI::App& app);
void addCompareCommand(CLI::App& app);
void addBenchCommand(CLI::App& app);
void addReleaseCommand(CLI::App& app);
void addViewCommand(CLI::App& app);

// Runs rtlab with the given arguments; returns the process exit code.
int run(int argc, char** argv);

}  // namespace rtlab::cli
