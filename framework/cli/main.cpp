// raylab: the course's command-line tool. `raylab --help` lists the commands.
#include "build_info.h"
#include "commands.h"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
    using namespace raylab;
    CLI::App app{"raylab: the ray-tracing labs of TP1 (premières images).\nThis program is the " +
                 std::string(build::kImpl) + " build: " + build::kLabOrigins};
    app.require_subcommand(1);
    cli::Context context{argc, argv, build::kImpl, 0, build::kScenesDir};
    cli::addFigureCommands(app, context);
    cli::addBenchCommand(app, context);
    cli::addGradeCommands(app, context);
    cli::addReferencesCommand(app, context);
    cli::addDistributeCommand(app, context);
    cli::addAutograderCommand(app, context);
    cli::addStudyAntialiasingCommand(app, context);
    cli::addBenchEffectsCommand(app, context);
    cli::addNumericsCommands(app, context);
    cli::addReportCommand(app, context);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raylab: error: %s\n", e.what());
        return 1;
    }
    return context.exitStatus;
}
