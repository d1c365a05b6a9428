#include "build_info.h"
#include "commands.h"

#include "grader/lab_catalog.h"
#include "grader/sandbox/process.h"
#include "src/messages.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>
#ifdef _WIN32
#include <process.h>
#else
#include <unistd.h>
#endif

namespace raylab::cli {

CLI::Validator threadCount() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            long long n = 0;
            const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
            if (error == std::errc::result_out_of_range || (error == std::errc() && n > kMaxThreads))
                return tr("cli.too_many_threads", {{"value", text}, {"max", std::to_string(kMaxThreads)}});
            if (error != std::errc() || end != text.data() + text.size() || n < 0)
                return tr("cli.not_threads", {{"value", text}, {"max", std::to_string(kMaxThreads)}});
            return "";
        },
        "0.." + std::to_string(kMaxThreads));
}

CLI::Validator positiveSeconds() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            char* end = nullptr;
            const double seconds = std::strtod(text.c_str(), &end);
            if (text.empty() || *end != '\0' || !std::isfinite(seconds) || !(seconds > 0.))
                return tr("cli.not_seconds", {{"value", text}});
            return "";
        },
        "SECONDS > 0");
}

CLI::Validator integerIn(std::int64_t low, std::int64_t high) {
    return CLI::Range(low, high).description(std::to_string(low) + ".." + std::to_string(high));
}

void Context::addRenderOptions(CLI::App* command) {
    command->add_option("--threads", threads, tr("cli.threads"))->check(threadCount());
    command->add_option("--scenes", scenes, tr("cli.scenes"))->check(CLI::ExistingDirectory);
}

void Context::addImplOption(CLI::App* command) {
    command->add_option("--impl", impl, tr("cli.impl"))
        ->check(CLI::IsMember({"student", "reference"}));
}

void addTimingCommand(CLI::App& app, Context& context, const std::string& name, const std::string& description,
                      int repeats, TimingRun run) {
    auto repeatsOption = std::make_shared<int>(repeats);
    CLI::App* command = app.add_subcommand(name, description);
    context.addImplOption(command);
    command->add_option("--repeats", *repeatsOption, tr("cli.bench_repeats"))
        ->check(integerIn(1, 100));
    context.addRenderOptions(command);
    command->callback([&context, repeatsOption, run] {
        if (!context.ranInOtherImpl()) context.exitStatus = run(context.scenes, context.threads, *repeatsOption);
    });
}

std::filesystem::path labsFolder() { return std::filesystem::path(build::kSourceDir) / "labs"; }

std::filesystem::path gradingFolder(const grader::LabDescription& lab) {
    return std::filesystem::path(build::kSourceDir) / "framework" / "grader" / "labs" / lab.id;
}

std::filesystem::path referencesFolder(const grader::LabDescription& lab) { return gradingFolder(lab) / "references"; }

std::vector<std::filesystem::path> referenceFolders(const std::string& given) {
    if (!given.empty()) return {given};
    std::vector<std::filesystem::path> folders;
    for (const grader::LabDescription& lab : courseLabs().labs) folders.push_back(referencesFolder(lab));
    return folders;
}

grader::LabCatalog courseLabs() { return grader::loadLabCatalog(labsFolder()); }

SceneDescription figureWithRole(const std::filesystem::path& scenes, std::string_view role) {
    return sceneWithRole(grader::loadFiguresInLabOrder(scenes, courseLabs()), role, scenes.empty() ? labsFolder() : scenes);
}

std::string labList(const grader::LabCatalog& labs) {
    std::string list;
    for (int n : labs.numbers()) list += " " + std::to_string(n);
    return tr("grade.labs_are", {{"labs", list}});
}

CLI::App* studyCommand(CLI::App& app) {
    try {
        return app.get_subcommand("study");
    } catch (const CLI::OptionNotFound&) {
        CLI::App* study = app.add_subcommand("study", tr("cli.study"));
        study->require_subcommand(1);
        return study;
    }
}

std::filesystem::path programInBuild(const std::string& name) {
    std::filesystem::path program = std::filesystem::path(build::kBinaryDir) / name;
#ifdef _WIN32
    program += ".exe";
#endif
    return program;
}

std::string thisProgram() { return build::kImpl == std::string("student") ? "raylab" : "raylab-reference"; }

bool Context::ranInOtherImpl() {
    if (impl == build::kImpl) return false;
    namespace fs = std::filesystem;
    const fs::path program = programInBuild(impl == "reference" ? "raylab-reference" : "raylab");
    std::error_code error;
    if (!fs::exists(program, error)) {
        const std::string why = tr("cli.no_build", {{"impl", tr("figures.impl_" + impl)}, {"program", program.string()}}) +
                                (impl == "reference" ? tr("cli.no_build_reference") : "");
        std::fprintf(stderr, "%s\n", tr("cli.error", {{"what", why}}).c_str());
        exitStatus = 1;
        return true;
    }
    std::vector<std::string> args{program.string()};
    for (int k = 1; k < argc; ++k) args.emplace_back(argv[k]);
    const std::vector<char*> cargs = grader::argumentPointers(args);
    std::fflush(stdout);
#ifdef _WIN32
    const auto status = _spawnv(_P_WAIT, program.string().c_str(), cargs.data());
    exitStatus = status < 0 ? 1 : int(status);
#else
    execv(program.c_str(), cargs.data());
    const std::string why = tr("cli.cannot_run", {{"program", program.string()}, {"why", std::strerror(errno)}});
    std::fprintf(stderr, "%s\n", tr("cli.error", {{"what", why}}).c_str());
    exitStatus = 1;
#endif
    return true;
}

} // namespace raylab::cli
