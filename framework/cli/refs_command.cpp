// PLACEHOLDER: replaced by the real command.
#include "framework/cli/commands.h"
namespace rtlab::cli {
void addRefsCommand(CLI::App& app) { (void)app; }
}  // namespace rtlab::cli
