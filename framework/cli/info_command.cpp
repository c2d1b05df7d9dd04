// PLACEHOLDER: replaced by the real command.
#include "framework/cli/commands.h"
namespace rtlab::cli {
void addInfoCommand(CLI::App& app) { app.add_subcommand("info", "(not built yet)"); }
}  // namespace rtlab::cli
