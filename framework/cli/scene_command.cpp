// PLACEHOLDER: replaced by the real command.
#include "framework/cli/commands.h"
namespace rtlab::cli {
void addSceneCommand(CLI::App& app) { app.add_subcommand("scene", "(not built yet)"); }
}  // namespace rtlab::cli
