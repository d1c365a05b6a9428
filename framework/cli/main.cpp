// raylab: the course's command-line tool. `raylab --help` lists the commands.
#include "build_info.h"
#include "commands.h"

#include "raylab/messages.h"

#include <cstdio>
#include <exception>
#include <string>
#include <string_view>

namespace {

// CLI11 would say "The following arguments were not expected"; name the command and list them.
std::string unknownCommand(CLI::App& app, int argc, char** argv) {
    if (argc < 2 || argv[1][0] == '-') return "";
    std::string names;
    for (const CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) {
        if (command->get_name() == argv[1]) return "";
        names += (names.empty() ? "" : ", ") + command->get_name();
    }
    return "unknown command '" + std::string(argv[1]) + "'; commands are: " + names + " (raylab --help says more)";
}

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
    cli::addAutograderCommand(app, context);
    cli::addStudyAntialiasingCommand(app, context);
    cli::addBenchEffectsCommand(app, context);
    cli::addNumericsCommands(app, context);
    cli::addReportCommand(app, context);
    if (const std::string unknown = unknownCommand(app, argc, argv); !unknown.empty()) {
        std::fprintf(stderr, "raylab: error: %s\n", unknown.c_str());
        return 1;
    }
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
