// raylab: the course's command-line tool. `raylab --help` lists the commands.
#include "build_info.h"
#include "commands.h"

#include "raylab/messages.h"

#include <cstdio>
#include <exception>
#include <string_view>

namespace {

// --lang is read before the commands run, wherever it stands on the line (`raylab grade --lang fr`),
// so that every message, the ones written while parsing included, is in that language.
void chooseLanguage(int argc, char** argv) {
    for (int k = 1; k < argc; ++k) {
        const std::string_view arg = argv[k];
        std::string_view value;
        if (arg == "--lang" && k + 1 < argc) value = argv[k + 1];
        else if (arg.substr(0, 7) == "--lang=") value = arg.substr(7);
        if (const auto language = raylab::parseLanguage(value)) raylab::setLanguage(*language);
    }
}

} // namespace

int main(int argc, char** argv) {
    using namespace raylab;
    CLI::App app{"raylab: the ray-tracing labs of TP1 (premières images).\nThis program is the " +
                 std::string(build::kImpl) + " build: " + build::kLabOrigins};
    app.require_subcommand(1);
    chooseLanguage(argc, argv);
    std::string lang = raylab::languageCode(raylab::language());
    app.add_option("--lang", lang, "the language of the messages, en or fr (default: from LC_ALL, LC_MESSAGES, LANG)")
        ->check(CLI::IsMember({"en", "fr"}));
    app.fallthrough(); // --lang after the subcommand too
    cli::Context context{argc, argv, build::kImpl, 0, build::kScenesDir};
    cli::addFigureCommands(app, context);
    cli::addBenchCommand(app, context);
    cli::addGradeCommands(app, context);
    cli::addReferencesCommand(app, context);
    cli::addDistributeCommand(app, context);
    cli::addStudyAntialiasingCommand(app, context);
    cli::addBenchEffectsCommand(app, context);
    cli::addNumericsCommands(app, context);
    cli::addReportCommand(app, context);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", raylab::tr("cli.error", {{"what", e.what()}}).c_str());
        return 1;
    }
    return context.exitStatus;
}
