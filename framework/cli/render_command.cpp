// PLACEHOLDER: replaced by the real command.
#include "framework/cli/commands.h"
namespace rtlab::cli {
void addRenderCommand(CLI::App& app) { app.add_subcommand("render", "(not built yet)"); }
}  // namespace rtlab::cli
