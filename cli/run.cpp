#include "cli/commands.h"
#include "framework/core/error.h"

#include <iostream>

namespace rtlab::cli {

int run(int argc, char** argv) {
    CLI::App app{"rtlab: ray-tracing acceleration structures and radiometry, by assignment"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "rtlab " RTLAB_VERSION);
    addInfoCommand(app);
    addRenderCommand(app);
    addHitsCommand(app);
    addSceneCommand(app);
    addGradeCommand(app);
    addExportPovCommand(app);
    addRefsCommand(app);
    addCompareCommand(app);
    addBenchCommand(app);
    addReleaseCommand(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e);  // prints help, version or the usage error
        return code == 0 ? 0 : 2;
    } catch (const NotImplemented& e) {
        std::cerr << "rtlab: " << e.what() << " (see docs/)\n";
        return 3;
    } catch (const std::exception& e) {
        std::cerr << "rtlab: " << e.what() << "\n";
        return 1;
    }
    return 0;
}

}  // namespace rtlab::cli
