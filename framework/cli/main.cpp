// raylab: the course's command-line tool. `raylab --help` lists the commands.
#include "build_info.h"
#include "commands.h"

#include "src/messages.h"
#include "src/text.h"
#include "src/windows_api.h"

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <regex>
#include <string>
#include <string_view>
#include <vector>

namespace {

// CLI11 would say "The following arguments were not expected"; name the command and list them.
std::string unknownCommand(CLI::App& app, int argc, char** argv) {
    if (argc < 2 || argv[1][0] == '-') return "";
    std::string names;
    for (const CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) {
        if (command->get_name() == argv[1]) return "";
        names += (names.empty() ? "" : ", ") + command->get_name();
    }
    return raylab::tr("cli.unknown_command", {{"command", argv[1]}, {"commands", names}});
}

// The commands a build without solutions/ (the students' tree) does not have, because their code
// holds a lab's answer: named as the instructors' rather than unknown. Empty when this one is not one.
std::string instructorsOnlyCommand(int argc, char** argv) {
#ifdef RAYLAB_HAVE_NUMERICS
    (void)argc;
    (void)argv;
    return "";
#else
    const auto is = [&](int k, const char* word) { return argc > k && std::string(argv[k]) == word; };
    if (is(1, "numerics")) return raylab::tr("cli.instructors_only", {{"command", "raylab numerics"}});
    if (is(1, "study") && is(2, "intersection"))
        return raylab::tr("cli.instructors_only", {{"command", "raylab study intersection"}});
    return "";
#endif
}

// CLI11 names an option's value with English words (TEXT:DIR, INT in [1 - 100]): each word the
// catalogue knows ([cli.type]) is said in the reader's language.
std::string typeNameInLanguage(const std::string& typeName) {
    static const std::regex word("[A-Za-z]+");
    const auto& catalogue = raylab::messageCatalogue(raylab::language());
    std::string said;
    auto from = typeName.cbegin();
    for (std::sregex_iterator it(typeName.begin(), typeName.end(), word), end; it != end; ++it) {
        said.append(from, (*it)[0].first);
        const auto known = catalogue.find("cli.type." + it->str());
        said += known != catalogue.end() ? known->second : it->str();
        from = (*it)[0].second;
    }
    return said.append(from, typeName.cend());
}

// The help's option column (" TEXT:DIR REQUIRED") with the value types' words in the reader's language.
class LanguageFormatter : public CLI::Formatter {
  public:
    std::string make_option_opts(const CLI::Option* option) const override {
        return typeNameInLanguage(CLI::Formatter::make_option_opts(option));
    }
};

// The command the words of the command line reached (`raylab grade`, `raylab study intersection`).
const CLI::App& commandReached(const CLI::App& app) {
    for (const CLI::App* command : app.get_subcommands())
        if (command->parsed()) return commandReached(*command);
    return app;
}

std::string commandPath(const CLI::App& command) {
    const CLI::App* parent = command.get_parent();
    return parent == nullptr ? "raylab" : commandPath(*parent) + " " + command.get_name();
}

// CLI11 lists the words it did not expect last first ("b a" for `a b`): in the command line's order.
std::vector<std::string> wordsInOrder(const std::string& listed) {
    std::vector<std::string> words;
    std::size_t from = 0;
    while (from <= listed.size()) {
        const std::size_t space = std::min(listed.find(' ', from), listed.size());
        words.insert(words.begin(), listed.substr(from, space - from));
        from = space + 1;
    }
    return words;
}

// Words the command did not expect: an option it does not have is named, with the ones it has.
std::string sayNotExpected(const CLI::App& app, const std::string& listed) {
    using raylab::tr;
    const std::vector<std::string> words = wordsInOrder(listed);
    std::string shown;
    for (const std::string& word : words) shown += (shown.empty() ? "" : " ") + word;
    const auto option = std::find_if(words.begin(), words.end(), [](const std::string& w) { return w.size() > 1 && w[0] == '-'; });
    if (option == words.end()) return tr("cli.not_expected", {{"args", shown}});
    const CLI::App& command = commandReached(app);
    std::string options;
    for (const CLI::Option* o : command.get_options())
        if (o != command.get_help_ptr() && o->get_name().rfind('-', 0) == 0) options += (options.empty() ? "" : ", ") + o->get_name();
    return tr("cli.not_an_option", {{"option", option->substr(0, option->find('='))}, {"command", commandPath(command)}, {"options", options}});
}

// CLI11's errors are English sentences around an option's name and a value; the common ones are said
// again in the reader's language with that name and value. Any other keeps CLI11's text.
std::string sayParseError(const CLI::App& app, const CLI::Error& error) {
    using raylab::tr;
    const std::string what = error.what();
    std::smatch m;
    static const std::regex notExpected("The following arguments? (?:was|were) not expected: (.*)");
    static const std::regex missingValue(R"((\S+): \d+ required (\S+) missing)");
    static const std::regex notInSet(R"((\S+): (.*) not in (\{.*\}))");
    // "low to high" (CLI11 2.3, Debian 12), "[low - high]" (CLI11 2.4, Debian 13)
    static const std::regex notInRange(R"((\S+): Value (.*) not in range \[?(\S+?)(?: to | - )(\S+?)\]?)");
    static const std::regex noDirectory(R"((\S+): Directory does not exist: (.*))");
    static const std::regex noFile(R"((\S+): File does not exist: (.*))");
    static const std::regex required(R"((\S+) is required)");
    static const std::regex notAllowed(R"(The value (.*) is not an allowed value for (\S+))");
    static const std::regex notConverted(R"(Could not convert: (\S+) = (.*))");
    static const std::regex atMost(R"((\S+): At Most (\d+) required but received (\d+))");
    if (std::regex_match(what, m, notExpected)) return sayNotExpected(app, m[1]);
    if (std::regex_match(what, m, missingValue))
        return tr("cli.missing_value", {{"option", m[1]}, {"type", typeNameInLanguage(m[2])}});
    if (std::regex_match(what, m, atMost)) return tr("cli.at_most", {{"option", m[1]}, {"max", m[2]}, {"count", m[3]}});
    // CLI::PositiveNumber is a range up to the largest double (CLI11 2.4 prints it rounded, 1.79769e+308).
    if (std::regex_match(what, m, notInRange) && std::strtod(m[4].str().c_str(), nullptr) >= 1e308)
        return tr("cli.not_positive", {{"option", m[1]}, {"value", m[2]}});
    if (std::regex_match(what, m, notInRange))
        return tr("cli.not_in_range", {{"option", m[1]}, {"value", m[2]}, {"low", m[3]}, {"high", m[4]}});
    if (std::regex_match(what, m, notInSet))
        return tr("cli.not_in_set", {{"option", m[1]}, {"value", m[2]}, {"allowed", m[3]}});
    if (std::regex_match(what, m, noDirectory)) return tr("cli.no_directory", {{"option", m[1]}, {"path", m[2]}});
    if (std::regex_match(what, m, noFile)) return tr("cli.no_file", {{"option", m[1]}, {"path", m[2]}});
    if (what == "A subcommand is required") return tr("cli.command_required");
    if (std::regex_match(what, m, required)) return tr("cli.required", {{"option", m[1]}});
    if (std::regex_match(what, m, notAllowed)) return tr("cli.not_a_value", {{"option", m[2]}, {"value", m[1]}});
    if (std::regex_match(what, m, notConverted)) return tr("cli.not_a_value", {{"option", m[1]}, {"value", m[2]}});
    return what;
}

// The help's headings in the reader's language, and the options' group, inherited by every command
// added after this.
void sayHelpInLanguage(CLI::App& app) {
    using raylab::tr;
    const auto formatter = std::make_shared<LanguageFormatter>();
    app.formatter(formatter);
    formatter->label("Usage", tr("cli.label_usage"));
    formatter->label("OPTIONS", tr("cli.label_options_upper"));
    formatter->label("Positionals", tr("cli.label_positionals"));
    formatter->label("SUBCOMMAND", tr("cli.label_subcommand"));
    formatter->label("SUBCOMMANDS", tr("cli.label_subcommand"));
    formatter->label("REQUIRED", tr("cli.label_required"));
    app.option_defaults()->group(tr("cli.label_options"));
    app.group(tr("cli.label_subcommands"));
    app.set_help_flag("-h,--help", tr("cli.help"));
    app.failure_message([](const CLI::App* failed, const CLI::Error& error) {
        // The words quoted are the command line's, of any bytes: an escape sequence shows as \x1B.
        return tr("cli.error", {{"what", raylab::printableText(sayParseError(*failed, error))}}) + "\n" + tr("cli.run_help") + "\n";
    });
}

// A command's help flag is made before it inherits the options' group: put it in that group.
void groupHelpFlags(CLI::App& command) {
    if (CLI::Option* help = command.get_help_ptr()) help->group(raylab::tr("cli.label_options"));
    for (CLI::App* subcommand : command.get_subcommands([](CLI::App*) { return true; })) groupHelpFlags(*subcommand);
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

#ifndef _WIN32
// A reader of the output that goes away (`raylab grade | head`) costs the lines it did not read, not
// the grade: writes fail, the run goes on and writes its reports. A handler, not SIG_IGN, so that the
// programs this one starts get the default again.
extern "C" void carryOnWithoutReader(int) {}
#endif

int main(int argc, char** argv) {
    using namespace raylab;
#ifdef _WIN32
    SetConsoleOutputCP(CP_UTF8); // the catalogues' French is UTF-8 (the console's code page is not)
#else
    std::signal(SIGPIPE, carryOnWithoutReader);
#endif
    chooseLanguage(argc, argv);
    CLI::App app{tr("cli.program", {{"impl", tr(std::string("figures.impl_") + build::kImpl)}, {"origins", build::kLabOrigins}})};
    sayHelpInLanguage(app);
    app.require_subcommand(1);
    std::string lang = raylab::languageCode(raylab::language());
    app.add_option("--lang", lang, tr("cli.lang"))->check(CLI::IsMember({"en", "fr"}));
    app.fallthrough(); // --lang after the subcommand too
    cli::Context context{argc, argv, build::kImpl, 0, ""};
    // Every command describes itself in the reader's language (tests/cli/test_cli_language.cpp).
#ifndef RAYLAB_GRADING_ONLY // a build for grading alone (RAYLAB_GRADING_ONLY, framework/CMakeLists.txt)
    cli::addFigureCommands(app, context);
    cli::addBenchCommand(app, context);
#endif
    cli::addGradeCommands(app, context);
    cli::addClassPageCommand(app, context);
#ifndef RAYLAB_GRADING_ONLY
    cli::addReferencesCommand(app, context);
    cli::addDistributeCommand(app, context);
#endif
    cli::addAutograderCommand(app, context);
#ifndef RAYLAB_GRADING_ONLY
    cli::addStudyAntialiasingCommand(app, context);
    cli::addBenchEffectsCommand(app, context);
#ifdef RAYLAB_HAVE_NUMERICS
    cli::addNumericsCommands(app, context);
#endif
#ifndef RAYLAB_NO_REPORT // left out where cmark is missing (RAYLAB_REPORT)
    cli::addReportCommand(app, context);
#endif
#ifndef RAYLAB_NO_WATCH // left out where cpp-httplib is missing (RAYLAB_WATCH)
    cli::addWatchCommand(app, context);
#endif
#endif
    groupHelpFlags(app);
    if (const std::string absent = instructorsOnlyCommand(argc, argv); !absent.empty()) {
        std::fprintf(stderr, "%s\n", raylab::tr("cli.error", {{"what", absent}}).c_str());
        return 1;
    }
    if (const std::string unknown = unknownCommand(app, argc, argv); !unknown.empty()) {
        std::fprintf(stderr, "%s\n", raylab::tr("cli.error", {{"what", raylab::printableText(unknown)}}).c_str());
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
