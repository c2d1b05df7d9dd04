// The subcommands of rtlab. Each lives in its own file and registers itself on the app.
#pragma once

// Declared, not included: CLI11 is header-only and costs every file that includes it about 11 s
// of compiling under the sanitizers (its validators are objects defined in the header), so only
// the files that parse a command line include <CLI/CLI.hpp>.
namespace CLI {
class App;
}

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

}  // namespace rtlab::cli
