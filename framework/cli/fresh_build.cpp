// A student edits a lab file and runs `raylab lab N` or `raylab grade` again: the programs that hold
// the labs' code are rebuilt first, so that what runs is what the student wrote. Where the running
// program cannot be rebuilt (Windows locks it), the command stops and names the newer file.
#include "build_info.h"
#include "commands.h"

#include "grader/course/submission.h"
#include "grader/lab_catalog.h"
#include "grader/sandbox/process.h"
#include "src/atomic_file.h"
#include "src/messages.h"

#include <algorithm>
#include <memory>
#include <optional>
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
    for (const grader::LabDescription& lab : catalog.labs) {
        // a lab built from its stub because its code did not compile is watched as the others
        const std::string origin = build::labOrigin(lab.number);
        if (origin == "labs" || origin == "stubs") folders.push_back(labsFolder() / lab.id);
    }
    return folders;
}

// The files of the grading build, as far as a run can see them change, but for the labs' code: the
// framework (with each lab's grading folder), cmake/, the top CMakeLists.txt and the course's list.
std::vector<fs::path> graderInputs() {
    std::vector<fs::path> inputs;
    const fs::path top = build::kSourceDir;
    for (const char* name : {"framework", "cmake", "CMakeLists.txt", "course.toml"}) inputs.push_back(top / name);
    return inputs;
}

// `cmake --build` of `targets` in this program's build folder, going on past errors (each lab is a
// target of its own: one that does not compile stops no other), its progress shown as it comes and
// its output kept. True when every target built.
bool build(const std::vector<std::string>& targets, grader::KeptOutput& output) {
    std::vector<std::string> argv{RAYLAB_CMAKE_COMMAND, "--build", build::kBuildDir, "--config", build::kBuildType, "--target"};
    argv.insert(argv.end(), targets.begin(), targets.end());
    const std::string generator = RAYLAB_CMAKE_GENERATOR;
    if (generator.find("Ninja") != std::string::npos) argv.insert(argv.end(), {"--", "-k", "0"});
    else if (generator.find("Makefiles") != std::string::npos) argv.insert(argv.end(), {"--", "-k"});
    std::fflush(stdout);
    const grader::ProcessResult built = grader::runProcess(argv, {.keepOutput = std::size_t(64) << 10, .echo = true});
    output.head += built.kept.head + built.error;
    output.tail = built.kept.tail;
    output.cut += built.kept.cut;
    return built.succeeded();
}

// Written when `targets` were rebuilt from here: a changed file that none of them is made from
// (a handout, a template of another program) is not seen as newer again at every run.
fs::path rebuiltStamp(const std::vector<std::string>& targets) {
    std::string name = "raylab-rebuilt";
    for (const std::string& target : targets) name += "-" + target;
    return fs::path(build::kBuildDir) / (name + ".stamp");
}

// "3, 6".
std::string numberList(const std::vector<int>& numbers) {
    std::string list;
    for (int n : numbers) list += (list.empty() ? "" : ", ") + std::to_string(n);
    return list;
}

// A students' tree keeps each lab as it was handed out in framework/stubs/: where a lab's code does
// not compile, the command-line tool is built with its stub instead (RAYLAB_STUB_LABS, the labs
// listed), so that the other labs' pictures are still drawn from what the student wrote.
bool hasStubs() {
    std::error_code error;
    return fs::is_directory(fs::path(build::kSourceDir) / "framework" / "stubs", error);
}

// The labs the build folder's configuration takes as stubs (its CMakeCache.txt).
std::vector<int> configuredStubLabs() {
    const std::optional<std::string> cache = readWholeFile(fs::path(build::kBuildDir) / "CMakeCache.txt");
    const std::string key = "\nRAYLAB_STUB_LABS:STRING=";
    std::vector<int> labs;
    if (!cache) return labs;
    const std::size_t at = cache->find(key);
    if (at == std::string::npos) return labs;
    std::istringstream list(cache->substr(at + key.size(), cache->find('\n', at + key.size()) - at - key.size()));
    for (std::string n; std::getline(list, n, ';');)
        if (!n.empty()) labs.push_back(std::atoi(n.c_str()));
    return labs;
}

// Configures the build folder again with `labs` as stubs.
bool configureStubLabs(const std::vector<int>& labs, grader::KeptOutput& output) {
    std::string list;
    for (int lab : labs) list += (list.empty() ? "" : ";") + std::to_string(lab);
    const grader::ProcessResult configured = grader::runProcess(
        {RAYLAB_CMAKE_COMMAND, "-S", build::kSourceDir, "-B", build::kBuildDir, "-DRAYLAB_STUB_LABS=" + list},
        {.keepOutput = std::size_t(64) << 10});
    if (!configured.succeeded()) output.tail += configured.kept.head + configured.kept.tail + configured.error;
    return configured.succeeded();
}

// The last write of `file`; the oldest time when it is not there.
fs::file_time_type writtenAt(const fs::path& file) {
    std::error_code error;
    const auto written = fs::last_write_time(file, error);
    return error ? fs::file_time_type::min() : written;
}

// Builds `targets` and says whether the first was built. When it is this program, in a students' tree,
// the labs that do not compile are then the tool's stubs, and those compiling again its student's code
// (one configuration more, when that changes). What the compiler said of the code is kept for the
// commands that report it (lastBuildProblem).
bool buildAndRecord(const std::vector<std::string>& targets, bool program) {
    grader::KeptOutput output;
    bool built = build(targets, output);
    const bool failed = !built;
    const std::vector<int> stubs = program && hasStubs() ? configuredStubLabs() : std::vector<int>{};
    if (program && hasStubs() && (!built || !stubs.empty())) {
        if (std::find(targets.begin(), targets.end(), "raylab-agents") == targets.end()) build({"raylab-agents"}, output);
        const grader::LabCatalog course = courseLabs();
        const std::vector<int> broken = grader::labsNotBuilt(build::kBinaryDir, labsFolder(), course, course.numbers());
        if (broken != stubs) {
            std::printf("%s\n", tr(broken.empty() ? "cli.stubs_restored" : "cli.stubs_for_broken_labs",
                                   {{"labs", numberList(broken)}})
                                    .c_str());
            if (configureStubLabs(broken, output)) built = build(targets, output);
        }
    }
    if (!built) built = build({targets.front()}, output);
    writeFileAtomically(lastBuildProblemFile(), failed ? grader::buildProblem(output) : "");
    return built;
}

// Marks `targets` as rebuilt from here now.
void stampRebuilt(const std::vector<std::string>& targets) {
    try {
        writeFileAtomically(rebuiltStamp(targets), "");
    } catch (const std::exception&) {
        // without it, the next run checks the build again: slower, never wrong
    }
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

void ensureFreshAgents(const Context& context, int lab) {
    bool isolated = false;
    const bool noAgent = grader::findAgents(build::kBinaryDir, courseLabs().numbers(), isolated).empty();
    const std::string agents = lab != 0 ? grader::labAgentTarget(build::kBinaryDir, lab) : "raylab-agents";
    ensureFreshBuild(context, {thisProgram(), agents}, BuildInputs::GradingBuild, noAgent,
                     lab != 0 ? std::vector<int>{lab} : courseLabs().numbers());
}

BuiltAgents agentsOfThisBuild(const grader::LabCatalog& course, const std::vector<int>& labs) {
    BuiltAgents built;
    built.agents = grader::findAgents(build::kBinaryDir, labs, built.isolated);
    built.unbuilt = grader::labsNotBuilt(build::kBinaryDir, labsFolder(), course, labs);
    std::erase_if(built.agents, [&](const grader::AgentPlan& a) {
        return std::find(built.unbuilt.begin(), built.unbuilt.end(), a.lab) != built.unbuilt.end();
    });
    if (!built.unbuilt.empty()) built.message = lastBuildProblem();
    return built;
}

fs::path lastBuildProblemFile() { return fs::path(build::kBuildDir) / "raylab-build-problem.txt"; }

std::string lastBuildProblem() { return readWholeFile(lastBuildProblemFile()).value_or(""); }

FreshBuild ensureFreshBuild(const Context& context, const std::vector<std::string>& targets, BuildInputs inputs, bool missing,
                            const std::vector<int>& agentLabs) {
    const fs::path program = programInBuild(targets.front());
    // The program, or the last rebuild from here when it is later; a program not built yet (the
    // figures' build makes raylab alone, not the grading agents) is built now.
    const auto built = std::max(writtenAt(program), writtenAt(rebuiltStamp(targets)));
    missing = missing || writtenAt(program) == fs::file_time_type::min();
    std::string file;
    if (!missing) {
        // The running program is built from this build's labs, and from the grader's files.
        const fs::path changed = newerSourceFile(inputs == BuildInputs::GradingBuild ? graderInputs() : studentLabFolders(false), built);
        if (inputs == BuildInputs::GradingBuild && changed.empty()) {
            // Only the labs' code may have changed: the grading programs run it, this program does not
            // (their last build, from here or by hand, is what counts: `raylab lab` rebuilds this
            // program alone).
            const std::vector<std::string> agents(targets.begin() + 1, targets.end());
            // Each lab's program against the files of the labs it is built from; a lab whose code did
            // not compile at the last try, unchanged since, is not tried again.
            const auto tried = std::max(writtenAt(rebuiltStamp(targets)), writtenAt(rebuiltStamp(agents)));
            const grader::LabCatalog course = courseLabs();
            const std::vector<int> stale = grader::labsNotBuilt(build::kBinaryDir, labsFolder(), course, agentLabs, tried);
            if (stale.empty()) return FreshBuild::Fresh;
            const fs::path changed = newerSourceFile(studentLabFolders(true), tried);
            const std::string lab = changed.empty() ? "labs/" : fs::relative(changed, build::kSourceDir).generic_string();
            const std::unique_ptr<FileLock> lock = grader::lockBuildFolder(build::kBuildDir);
            std::printf("%s\n", tr("cli.rebuilding", {{"file", lab}}).c_str());
            buildAndRecord(agents, false); // a lab that does not compile is the grade's to report
            stampRebuilt(agents);
            return FreshBuild::Rebuilt;
        }
        if (changed.empty()) return FreshBuild::Fresh;
        file = fs::relative(changed, build::kSourceDir).generic_string();
    }
#ifdef _WIN32
    if (!missing) { // a running program's file cannot be replaced
        const std::string stale =
            tr("cli.stale_build", {{"file", file}, {"build", build::kBuildDir}, {"config", build::kBuildType}});
        std::fprintf(stderr, "%s\n", tr("cli.error", {{"what", stale}}).c_str());
        return FreshBuild::Stale;
    }
#endif
    // One build at a time in the folder: a second command waits, then finds built what the first built.
    const std::unique_ptr<FileLock> lock = grader::lockBuildFolder(build::kBuildDir);
    std::printf("%s\n", missing ? tr("cli.building_agents").c_str() : tr("cli.rebuilding", {{"file", file}}).c_str());
    if (!buildAndRecord(targets, true)) return FreshBuild::BuildFailed;
    stampRebuilt(targets);
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
