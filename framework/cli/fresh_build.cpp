// A student edits a lab file and runs `raylab lab N` or `raylab grade` again: the programs that hold
// the labs' code are rebuilt first, so that what runs is what the student wrote. Where the running
// program cannot be rebuilt (Windows locks it), the command stops and names the newer file.
#include "build_info.h"
#include "commands.h"

#include "grader/lab_catalog.h"
#include "grader/sandbox/process.h"
#include "src/messages.h"

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

// Rebuilds `targets` in this program's build folder; true when the build succeeded.
bool rebuild(const std::vector<std::string>& targets) {
    std::vector<std::string> argv{RAYLAB_CMAKE_COMMAND, "--build", build::kBuildDir, "--config", build::kBuildType, "--target"};
    argv.insert(argv.end(), targets.begin(), targets.end());
    std::fflush(stdout);
    return grader::runProcess(argv).succeeded();
}

} // namespace

fs::path newerLabFile(const std::vector<fs::path>& labFolders, const fs::path& program) {
    std::error_code error;
    const auto built = fs::last_write_time(program, error);
    if (error) return {};
    for (const fs::path& folder : labFolders)
        for (const auto& entry : fs::directory_iterator(folder, error)) {
            const std::string extension = entry.path().extension().string();
            if (extension != ".cpp" && extension != ".h") continue;
            const auto written = fs::last_write_time(entry.path(), error);
            if (!error && written > built) return entry.path();
        }
    return {};
}

FreshBuild ensureFreshBuild(const Context& context, const fs::path& program, const std::vector<std::string>& targets,
                            bool runningProgram) {
    std::error_code error;
    if (!runningProgram && !fs::exists(program, error)) { // the figures' build makes raylab alone
        std::printf("%s\n", tr("cli.building_agents").c_str());
        return rebuild(targets) ? FreshBuild::Rebuilt : FreshBuild::BuildFailed;
    }
    // The running program is built from this build's labs; the agents (the other programs) from labs/ alone.
    const fs::path changed = newerLabFile(studentLabFolders(!runningProgram), program);
    if (changed.empty()) return FreshBuild::Fresh;
    const std::string file = fs::relative(changed, build::kSourceDir).generic_string();
#ifdef _WIN32
    if (runningProgram) { // a running program's file cannot be replaced
        const std::string stale =
            tr("cli.stale_build", {{"file", file}, {"build", build::kBuildDir}, {"config", build::kBuildType}});
        std::fprintf(stderr, "%s\n", tr("cli.error", {{"what", stale}}).c_str());
        return FreshBuild::Stale;
    }
#endif
    std::printf("%s\n", tr("cli.rebuilding", {{"file", file}}).c_str());
    if (!rebuild(targets)) return FreshBuild::BuildFailed;
    if (!runningProgram) return FreshBuild::Rebuilt;
#ifndef _WIN32
    // Run the new program in this one's place, once (RAYLAB_REBUILT stops a loop on a skewed clock).
    if (std::getenv("RAYLAB_REBUILT") == nullptr) {
        setenv("RAYLAB_REBUILT", "1", 1);
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
