#include "grader/course/submission.h"

#include "grader/sandbox/process.h"
#include "src/messages.h"

#include <ctime>
#include <fstream>
#include <functional>
#include <sstream>

namespace raylab::grader {

namespace fs = std::filesystem;

namespace {

// A submission's whole build, every lab file together (the build guard stops a compile past it): far
// beyond an honest one (seconds), a bound on one that makes each file expand to the compiler's limits.
constexpr long long kBuildSeconds = 180;

// What a CMake cache value or list item cannot hold as it is.
constexpr const char* kCmakeUnsafe = "\n\r;\"\\$#[]";

fs::path agentFile(const fs::path& binDir, const std::string& name) {
#ifdef _WIN32
    return binDir / (name + ".exe");
#else
    return binDir / name;
#endif
}

// The submission's folder as CMake can hold it: a cache value cannot hold a newline, and `;` or a
// quote would change its meaning, so an unusual name is reached through a link of a plain name.
// The link's name is the folder's own (hashed): a build folder shared by a class must never take
// one student's objects, built from the same paths, for another's.
fs::path cmakeSafe(const fs::path& labs, const fs::path& buildDir) {
    const std::string path = fs::absolute(labs).generic_string();
    if (path.find_first_of(kCmakeUnsafe) == std::string::npos) return fs::absolute(labs);
    std::ostringstream name;
    name << "submission-" << std::hex << std::hash<std::string>{}(path);
    const fs::path link = fs::absolute(buildDir) / name.str();
    std::error_code ignored;
    fs::remove(link, ignored);
    fs::create_directory_symlink(fs::absolute(labs), link);
    return link;
}

// The compiler launcher that runs each compiler through ccache, with paths rewritten relative to the
// folder the sources and the build share: the students of a class build the same framework files in
// folders of the same depth, so every student after the first compiles only their labs (about 12 s
// rather than 90 on 2 cores). Empty when ccache is not there or the folder cannot be a CMake list item.
std::string ccacheLauncher(const Toolchain& tools, const fs::path& sourceDir, const fs::path& buildDir) {
    if (tools.ccache.empty()) return "";
    const fs::path source = fs::absolute(sourceDir).lexically_normal(), build = fs::absolute(buildDir).lexically_normal();
    fs::path shared;
    for (auto s = source.begin(), b = build.begin(); s != source.end() && b != build.end() && *s == *b; ++s, ++b)
        shared /= *s;
    const std::string base = shared.generic_string();
    if (base.find_first_of(kCmakeUnsafe) != std::string::npos) return "";
    return tools.cmake + ";-E;env;CCACHE_BASEDIR=" + base + ";" + tools.ccache.generic_string();
}

// A refusal of raylab-build-guard (build_guard.cpp), in the reader's language; empty for another line.
std::string guardRefusal(const std::string& line) {
    const std::string prefix = "raylab-build-guard: ";
    if (line.rfind(prefix, 0) != 0) return "";
    const std::size_t colon = line.find(": ", prefix.size());
    if (colon == std::string::npos) return line;
    const std::string why = line.substr(prefix.size(), colon - prefix.size()), rest = line.substr(colon + 2);
    const std::size_t arrow = rest.find(" <- ");
    const std::string source = rest.substr(0, arrow), read = arrow == std::string::npos ? "" : rest.substr(arrow + 4);
    if (why == "outside") return tr("build.guard_outside", {{"source", source}, {"file", read}});
    if (why == "stopped") return tr("build.guard_stopped", {{"source", source}});
    if (why == "build-time") return tr("build.guard_build_time", {{"source", source}, {"seconds", std::to_string(kBuildSeconds)}});
    return tr("build.guard_unchecked", {{"source", source}});
}

// make's and ninja's own lines ("gmake[2]: *** [...] Error 1", "FAILED: ..."): they repeat the
// compiler's errors without their cause.
bool buildToolLine(const std::string& line) {
    for (const char* tool : {"make", "gmake", "mingw32-make", "ninja: ", "FAILED: "})
        if (line.rfind(tool, 0) == 0) return true;
    return false;
}

// The lines that say what went wrong, not the whole log.
std::string errorLines(const fs::path& log) {
    std::ifstream in(log);
    std::string all, errors;
    int count = 0;
    for (std::string line; std::getline(in, line);) {
        if (const std::string refusal = guardRefusal(line); !refusal.empty()) line = "error: " + refusal;
        all += line + "\n";
        const bool error = !buildToolLine(line) && (line.find("error") != std::string::npos || line.find("Error") != std::string::npos ||
                                                    line.find("out of memory") != std::string::npos); // cc1plus past the guard's limit
        if (error && errors.find(line + "\n") == std::string::npos && count++ < 40) errors += line + "\n"; // once each
    }
    if (!errors.empty()) return errors;
    if (all.size() > 3000) all.erase(0, all.size() - 3000).insert(0, "...");
    return all;
}

// The agent of one lab, built with the other labs from the reference (framework/grader/CMakeLists.txt).
fs::path labAgent(const fs::path& binDir, int lab) { return agentFile(binDir, "raylab-agent-lab" + std::to_string(lab)); }

// CMake's configuration of a grading build: the agents from `submission` (empty: labs/), and the
// labs each lab uses (RAYLAB_LAB_USES_<n>, read by framework/grader/CMakeLists.txt: CMake does not
// read lab.toml).
std::vector<std::string> configureCommand(const Toolchain& tools, const fs::path& sourceDir, const fs::path& buildDir,
                                          const std::string& submission, const LabCatalog& course) {
    std::vector<std::string> configure{tools.cmake, "-S", fs::absolute(sourceDir).string(), "-B",
                                       fs::absolute(buildDir).string(), "-DCMAKE_BUILD_TYPE=Release",
                                       "-DBUILD_TESTING=OFF", "-DRAYLAB_SUBMISSION_DIR=" + submission,
                                       // Grading needs the same pictures, not their speed: links without
                                       // link-time optimisation take a fraction of the time.
                                       "-DRAYLAB_LTO=OFF"};
    if (const std::string launcher = ccacheLauncher(tools, sourceDir, buildDir); !launcher.empty())
        configure.push_back("-DCMAKE_CXX_COMPILER_LAUNCHER=" + launcher);
    for (const LabDescription& lab : course.labs) {
        std::string uses;
        for (int other : lab.uses) {
            if (!uses.empty()) uses += ';';
            uses += std::to_string(other);
        }
        configure.push_back("-DRAYLAB_LAB_USES_" + std::to_string(lab.number) + "=" + uses);
    }
    std::error_code error;
    if (!tools.generator.empty() && !fs::exists(buildDir / "CMakeCache.txt", error))
        configure.insert(configure.end(), {"-G", tools.generator});
    return configure;
}

// `cmake --build` of one target, in Release (a multi-configuration generator, Visual Studio, would
// build Debug otherwise), on 2 cores.
std::vector<std::string> buildCommand(const Toolchain& tools, const fs::path& buildDir, const std::string& target) {
    return {tools.cmake, "--build", fs::absolute(buildDir).string(), "--config", "Release", "--target", target, "-j", "2"};
}

} // namespace

std::vector<AgentPlan> findAgents(const fs::path& binDir, const std::vector<int>& labs, bool& isolated) {
    std::vector<AgentPlan> agents;
    std::error_code error;
    isolated = !labs.empty() && fs::exists(labAgent(binDir, labs.front()), error);
    if (isolated)
        for (int lab : labs) agents.push_back({labAgent(binDir, lab), lab});
    else if (fs::exists(agentFile(binDir, "raylab-agent"), error))
        agents.push_back({agentFile(binDir, "raylab-agent"), 0});
    return agents;
}

bool buildGradingKit(const Toolchain& tools, const fs::path& sourceDir, const fs::path& buildDir, const fs::path& log) {
    fs::create_directories(buildDir);
    std::error_code error;
    fs::remove(log, error);
    const ProcessOptions toLog{{}, log};
    return runProcess(configureCommand(tools, sourceDir, buildDir, "", LabCatalog{}), toLog).succeeded() &&
           runProcess(buildCommand(tools, buildDir, "raylab-grading-kit"), toLog).succeeded();
}

SubmissionBuild buildSubmission(const Toolchain& tools, const fs::path& sourceDir, const fs::path& labs,
                                const fs::path& buildDir, const LabCatalog& course, const fs::path& log) {
    SubmissionBuild b;
    const std::vector<int> numbers = course.numbers();
    fs::create_directories(buildDir);
    b.log = fs::absolute(log.empty() ? buildDir / "build.log" : log);
    const fs::path bin = buildDir / "bin";
    // A build folder serves a whole class: the last student's agents must not pass for these.
    std::error_code error;
    fs::remove(agentFile(bin, "raylab-agent"), error);
    for (int lab : numbers) fs::remove(labAgent(bin, lab), error);
    const std::vector<std::string> configure =
        configureCommand(tools, sourceDir, buildDir, cmakeSafe(labs, buildDir).generic_string(), course);
    std::vector<std::string> build = buildCommand(tools, buildDir, "raylab-submission-agents");
    if (tools.generator.find("Ninja") != std::string::npos) build.insert(build.end(), {"--", "-k", "0"});
    else if (tools.generator.find("Makefiles") != std::string::npos) build.insert(build.end(), {"--", "-k"});
    fs::remove(b.log, error);
    const ProcessOptions toLog{{}, b.log};
    const ProcessResult configured = runProcess(configure, toLog);
    if (!configured.succeeded()) {
        b.compilerMessage = configured.started ? errorLines(b.log) : configured.error;
        b.brokenLabs = numbers;
        return b;
    }
    // What no student changes first (nothing to do in a class, whose kit is built), so that the
    // build's deadline is the student's files' alone; a failure there shows in the build below.
    runProcess(buildCommand(tools, buildDir, "raylab-grading-kit"), toLog);
    ProcessOptions toBuild = toLog;
    toBuild.environment = {"RAYLAB_BUILD_DEADLINE=" + std::to_string(std::time(nullptr) + kBuildSeconds)};
    const ProcessResult built = runProcess(build, toBuild);
    if (!built.succeeded()) b.compilerMessage = built.started ? errorLines(b.log) : built.error;
    b.isolated = fs::is_directory(sourceDir / "solutions", error);
    if (b.isolated) {
        for (int lab : numbers) {
            const fs::path program = labAgent(bin, lab);
            if (fs::exists(program, error)) b.agents.push_back({program, lab});
            else b.brokenLabs.push_back(lab);
        }
    } else if (fs::exists(agentFile(bin, "raylab-agent"), error)) {
        b.agents.push_back({agentFile(bin, "raylab-agent"), 0});
    } else {
        // Some lab did not compile: each lab's own agent (the labs it uses from the submission, the
        // others' stubs) grades it when its labs compiled.
        for (int lab : numbers) {
            const fs::path program = labAgent(bin, lab);
            if (fs::exists(program, error)) b.agents.push_back({program, lab});
            else b.brokenLabs.push_back(lab);
        }
    }
    return b;
}

} // namespace raylab::grader
