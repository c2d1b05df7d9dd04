// PLACEHOLDER: replaced by the real command.
#include "framework/cli/commands.h"
namespace rtlab::cli {
void addGradeCommand(CLI::App& app) { app.add_subcommand("grade", "(not built yet)"); }
}  // namespace rtlab::cli
