// A student edits a lab file and runs `raylab lab N` or `raylab grade` again: the programs that hold
// the labs' code are rebuilt first, so that what runs is what the student wrote. Where the running
// program cannot be rebuilt (Windows locks it), the command stops and names the newer file.
#include "build_info.h"
#include "commands.h"

#include "grader/lab_catalog.h"
#include "grader/sandbox/process.h"
#include "src/atomic_file.h"
#include "src/messages.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#ifndef _WIN32
#include <unistd.h>
#endif

namespace raylab::cli {

namespace fs = std::filesystem;

namespace {

// The lab folders of labs/: all of them, or those this program took from there (build::kLabOrigins:
// "lab1=labs lab2=solutions ...").
std::vector<fs::path> studentLabFolders(bool everyLab) {
    std::vector<fs::path> folders;
    const grader::LabCatalog catalog = courseLabs();
    if (everyLab) {
        for (const grader::LabDescription& lab : catalog.labs) folders.push_back(labsFolder() / lab.id);
        return folders;
    }
    std::istringstream origins(build::kLabOrigins);
    for (std::string origin; origins >> origin;) {
        const auto equals = origin.find('=');
        if (equals == std::string::npos || origin.substr(equals + 1) != "labs") continue;
        const int number = std::atoi(origin.c_str() + 3); // "labN"
        if (const grader::LabDescription* lab = catalog.lab(number)) folders.push_back(labsFolder() / lab->id);
    }
    return folders;
}

// The files that make the grading build, as far as a run can see them change: every lab's folder
// of labs/, the framework (with each lab's grading folder), cmake/, the top CMakeLists.txt and the
// course's list of labs.
std::vector<fs::path> gradingBuildInputs() {
    std::vector<fs::path> inputs = studentLabFolders(true);
    const fs::path top = build::kSourceDir;
    for (const char* name : {"framework", "cmake", "CMakeLists.txt", "course.toml"}) inputs.push_back(top / name);
    return inputs;
}

// Rebuilds `targets` in this program's build folder; true when the build succeeded.
bool rebuild(const std::vector<std::string>& targets) {
    std::vector<std::string> argv{RAYLAB_CMAKE_COMMAND, "--build", build::kBuildDir, "--config", build::kBuildType, "--target"};
    argv.insert(argv.end(), targets.begin(), targets.end());
    std::fflush(stdout);
    return grader::runProcess(argv).succeeded();
}

// Written when `targets` were rebuilt from here: a changed file that none of them is made from
// (a handout, a template of another program) is not seen as newer again at every run.
fs::path rebuiltStamp(const std::vector<std::string>& targets) {
    std::string name = "raylab-rebuilt";
    for (const std::string& target : targets) name += "-" + target;
    return fs::path(build::kBuildDir) / (name + ".stamp");
}

} // namespace

fs::path newerSourceFile(const std::vector<fs::path>& inputs, fs::file_time_type since) {
    std::error_code error;
    const auto isNewer = [since](const fs::path& file) {
        const std::string extension = file.extension().string();
        if (extension == ".md" || extension == ".png") return false; // read by people, or at run time
        std::error_code unreadable;
        const auto written = fs::last_write_time(file, unreadable);
        return !unreadable && written > since;
    };
    for (const fs::path& input : inputs) {
        if (fs::is_regular_file(input, error)) {
            if (isNewer(input)) return input;
            continue;
        }
        for (auto entry = fs::recursive_directory_iterator(input, error); !error && entry != fs::recursive_directory_iterator();
             entry.increment(error)) {
            if (entry->path().filename().string().starts_with(".")) { // .git, an editor's files
                if (entry->is_directory(error)) entry.disable_recursion_pending();
                continue;
            }
            if (entry->is_regular_file(error) && isNewer(entry->path())) return entry->path();
        }
    }
    return {};
}

FreshBuild ensureFreshBuild(const Context& context, const std::vector<fs::path>& programs,
                            const std::vector<std::string>& targets, BuildInputs inputs, bool runningProgram) {
    std::error_code error;
    // The oldest program, or the last rebuild from here when it is later; a program not built yet
    // (the figures' build makes raylab alone) is built now.
    auto built = fs::file_time_type::max();
    bool missing = false;
    for (const fs::path& program : programs) {
        const auto written = fs::last_write_time(program, error);
        missing = missing || error;
        if (!error) built = std::min(built, written);
    }
    const auto stamp = fs::last_write_time(rebuiltStamp(targets), error);
    if (!error) built = std::max(built, stamp);
    std::string file;
    if (!missing) {
        // The running program is built from this build's labs; the grading build from all it compiles.
        const fs::path changed =
            newerSourceFile(inputs == BuildInputs::GradingBuild ? gradingBuildInputs() : studentLabFolders(false), built);
        if (changed.empty()) return FreshBuild::Fresh;
        file = fs::relative(changed, build::kSourceDir).generic_string();
    }
#ifdef _WIN32
    if (runningProgram && !missing) { // a running program's file cannot be replaced
        const std::string stale =
            tr("cli.stale_build", {{"file", file}, {"build", build::kBuildDir}, {"config", build::kBuildType}});
        std::fprintf(stderr, "%s\n", tr("cli.error", {{"what", stale}}).c_str());
        return FreshBuild::Stale;
    }
#endif
    std::printf("%s\n", missing ? tr("cli.building_agents").c_str() : tr("cli.rebuilding", {{"file", file}}).c_str());
    if (!rebuild(targets)) return FreshBuild::BuildFailed;
    try {
        writeFileAtomically(rebuiltStamp(targets), "");
    } catch (const std::exception&) {
        // without it, the next run checks the build again: slower, never wrong
    }
    if (!runningProgram) return FreshBuild::Rebuilt;
#ifndef _WIN32
    // Run the new program in this one's place, once (RAYLAB_REBUILT stops a loop on a skewed clock).
    if (std::getenv("RAYLAB_REBUILT") == nullptr) {
        setenv("RAYLAB_REBUILT", "1", 1);
        const fs::path& program = programs.front();
        std::vector<std::string> args{program.string()};
        for (int k = 1; k < context.argc; ++k) args.emplace_back(context.argv[k]);
        const std::vector<char*> cargs = grader::argumentPointers(args);
        std::fflush(stdout);
        execv(program.c_str(), cargs.data());
        std::fprintf(stderr, "%s\n",
                     tr("cli.error", {{"what", tr("cli.cannot_run", {{"program", program.string()}, {"why", std::strerror(errno)}})}}).c_str());
    }
#else
    (void)context;
#endif
    return FreshBuild::Rebuilt;
}

} // namespace raylab::cli
