// PLACEHOLDER: replaced by the real command.
#include "framework/cli/commands.h"
namespace rtlab::cli {
void addHitsCommand(CLI::App& app) { app.add_subcommand("hits", "(not built yet)"); }
}  // namespace rtlab::cli
