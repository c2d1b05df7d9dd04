#include "cli/run.h"

#include "cli/commands.h"
#include "cli/this_build.h"
#include "framework/core/error.h"
#include "framework/core/untrusted_text.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <string>

namespace rtlab::cli {

int run(int argc, char** argv) {
    CLI::App app{"rtlab: ray-tracing acceleration structures and radiometry, by assignment"};
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string("rtlab ") + version());
    addInfoCommand(app);
    addRenderCommand(app);
    addHitsCommand(app);
    addSceneCommand(app);
    addGradeCommand(app);
    addExportPovCommand(app);
    addExportBlenderCommand(app);
    addRefsCommand(app);
    addCompareCommand(app);
    addBenchCommand(app);
    addReleaseCommand(app);
    addViewCommand(app);
    // CLI11 reports a word that is no subcommand as "A subcommand is required", which hides
    // the typo: name it and list what there is instead.
    if (argc > 1 && argv[1][0] != '-') {
        std::string word = argv[1], names;
        bool known = false;
        for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
            known = known || sub->check_name(word);
            names += (names.empty() ? "" : ", ") + sub->get_name();
        }
        if (!known) {
            std::cerr << "rtlab: unknown command '" << grader::escapeUntrusted(word, grader::TextLayout::OneLine) << "' (commands: " << names
                      << "; rtlab --help)\n";
            return 2;
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e);  // prints help, version or the usage error
        return code == 0 ? 0 : 2;
    } catch (const NotImplemented& e) {
        std::cerr << "rtlab: " << grader::escapeUntrusted(e.what()) << " (see docs/)\n";
        return 3;
    } catch (const std::exception& e) {
        // Messages quote file names and file contents (a ray file's token, a scene's names):
        // escaped, so a terminal never obeys bytes that came from a file.
        std::cerr << "rtlab: " << grader::escapeUntrusted(e.what()) << "\n";
        return 1;
    }
    return 0;
}

}  // namespace rtlab::cli
