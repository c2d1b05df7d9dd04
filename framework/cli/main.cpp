// rtlab and rtlab-solution share this entry point; they differ only in which implementation
// of the assignments they link (docs/layout.md).
#include "framework/cli/commands.h"

int main(int argc, char** argv) { return rtlab::cli::run(argc, argv); }
