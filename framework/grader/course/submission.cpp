#include "grader/course/submission.h"

#include "grader/sandbox/build_limits.h"
#include "grader/sandbox/process.h"
#include "src/atomic_file.h"
#include "src/messages.h"
#include "src/text.h"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <functional>
#include <iomanip>
#include <set>
#include <sstream>
#include <system_error>

namespace raylab::grader {

namespace fs = std::filesystem;

namespace {

// A submission's whole build, every lab file together (the build guard stops a compile past it): far
// beyond an honest one (seconds), a bound on one that makes each file expand to the compiler's limits.
constexpr long long kBuildSeconds = 180;

// What a CMake cache value or list item cannot hold as it is.
constexpr const char* kCmakeUnsafe = "\n\r;\"\\$#[]";

// A build's output kept in its log: its first and last 64 KB, the first errors and how it ended. A
// submission can make the compiler write a gigabyte (a template error repeated); a person reads the
// first errors anyway, and the results disk of a class must not fill with them.
constexpr std::size_t kLogKeptBytes = std::size_t(64) << 10;

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

// "1,073,612,345": a count of bytes as a person reads it, in the reader's language.
std::string grouped(std::uint64_t count) {
    std::string digits = std::to_string(count), text;
    const std::string separator = tr("number.thousands");
    for (std::size_t k = 0; k < digits.size(); ++k) {
        if (k > 0 && (digits.size() - k) % 3 == 0) text += separator;
        text += digits[k];
    }
    return text;
}

// "32 MB", "64.8 MB": a size as the report names it (a program just over its limit is not "64 MB").
std::string megabytes(std::uint64_t bytes) {
    std::ostringstream count;
    if (bytes % (std::uint64_t(1) << 20) == 0) count << (bytes >> 20);
    else count << std::fixed << std::setprecision(1) << double(bytes) / double(std::uint64_t(1) << 20);
    return tr("number.megabytes", {{"count", count.str()}});
}

// A program's kept output as its log holds it: the head, a line saying how much was cut, the tail.
std::string logText(const KeptOutput& kept) {
    if (kept.cut == 0) return kept.head + kept.tail;
    return kept.head + "\n" + tr("build.output_cut", {{"bytes", grouped(kept.cut)}}) + "\n" + kept.tail;
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
    if (why == "time") return tr("build.guard_time", {{"source", source}});
    if (why == "killed") return tr("build.guard_killed", {{"source", source}});
    if (why == "build-time")
        return tr("build.guard_build_time", {{"source", source}, {"seconds", std::to_string(kBuildSeconds)}});
    return tr("build.guard_unchecked", {{"source", source}});
}

// The build tools' words for a limit the compiler reached, and the cause a person acts on instead:
// "virtual memory exhausted" and "Killed signal terminated program cc1plus" (the kernel's answer to a
// compiler out of memory) say nothing to a student.
struct LimitSign {
    const char* words;
    const char* cause; // a message key
};
constexpr LimitSign kLimitSigns[] = {
    {"virtual memory exhausted", "build.out_of_memory"},
    {"out of memory allocating", "build.out_of_memory"},
    {"Cannot allocate memory", "build.out_of_memory"},
    {"Killed signal terminated program", "build.out_of_memory"},
    {"File size limit exceeded", "build.file_too_big"},
};

// make's and ninja's own lines ("gmake[2]: *** [...] Error 1", "FAILED: ..."): they repeat the
// compiler's errors without their cause.
bool buildToolLine(const std::string& line) {
    for (const char* tool : {"make", "gmake", "mingw32-make", "ninja: ", "FAILED: "})
        if (line.rfind(tool, 0) == 0) return true;
    return false;
}

} // namespace

std::string buildProblem(const KeptOutput& output) {
    std::istringstream in(logText(output));
    std::string all, causes, errors;
    std::set<std::string> said;
    const auto sayOnce = [&](std::string& to, const std::string& line) {
        if (said.insert(line).second) to += line + "\n";
    };
    int count = 0;
    for (std::string line; std::getline(in, line);) {
        if (const std::string refusal = guardRefusal(line); !refusal.empty()) {
            // A compiler stopped by its limits: a cause; a file read outside: the code's error.
            const bool limit = line.rfind("raylab-build-guard: time: ", 0) == 0 ||
                               line.rfind("raylab-build-guard: build-time: ", 0) == 0 ||
                               line.rfind("raylab-build-guard: killed: ", 0) == 0;
            if (limit) {
                sayOnce(causes, refusal);
                continue;
            }
            line = "error: " + refusal;
        }
        all += line + "\n";
        const auto sign = std::find_if(std::begin(kLimitSigns), std::end(kLimitSigns),
                                       [&](const LimitSign& s) { return line.find(s.words) != std::string::npos; });
        if (sign != std::end(kLimitSigns)) {
            sayOnce(causes, tr(sign->cause, {{"limit", megabytes(kCompilerFileBytes)}}));
            continue;
        }
        const bool error =
            !buildToolLine(line) && (line.find("error") != std::string::npos || line.find("Error") != std::string::npos);
        if (error && count < 40 && said.count(line) == 0) { // once each
            sayOnce(errors, line);
            ++count;
        }
    }
    if (output.cut > 0) {
        const std::string kept = tr("number.kilobytes", {{"count", std::to_string(2 * (kLogKeptBytes >> 10))}});
        causes += tr("build.output_was_cut", {{"kept", kept}, {"bytes", grouped(output.cut)}}) + "\n";
    }
    if (!causes.empty() || !errors.empty()) return causes + errors;
    if (all.size() > 3000) all.erase(0, all.size() - 3000).insert(0, "...");
    return all;
}

namespace {

// Whether `program` was built and is no larger than the limit. One larger is removed (the build
// folder may be a class's, shared) and named first in `b`'s message.
bool usableProgram(const fs::path& program, SubmissionBuild& b) {
    std::error_code error;
    const std::uintmax_t size = fs::file_size(program, error);
    if (error) return false;
    if (size <= kAgentProgramBytes) return true;
    fs::remove(program, error);
    const std::string refused = tr("build.program_too_big", {{"program", program.filename().string()},
                                                             {"size", megabytes(size)},
                                                             {"limit", megabytes(kAgentProgramBytes)}});
    b.compilerMessage.insert(0, refused + "\n");
    return false;
}

// A build that failed for want of room is no fault of the submission: it is said as a full disk (a
// class run stops on it, class_run.h), not graded as a compile error. The build's words alone are not
// enough (a submission can print them): the disk must be nearly full too.
void requireRoom(const KeptOutput& output, const fs::path& buildDir) {
    if ((output.head + output.tail).find("No space left on device") == std::string::npos) return;
    std::error_code error;
    const fs::space_info space = fs::space(buildDir, error);
    if (!error && space.available >= kCompilerFileBytes) return;
    throw fs::filesystem_error("the build stopped on a full disk", buildDir,
                               std::make_error_code(std::errc::no_space_on_device));
}

// The agent of one lab, built with the other labs from the reference (framework/grader/CMakeLists.txt).
fs::path labAgent(const fs::path& binDir, int lab) { return agentFile(binDir, "raylab-agent-lab" + std::to_string(lab)); }
// The agent of one lab where there is no reference: the labs it uses from the same code, the others' stubs.
fs::path ownLabAgent(const fs::path& binDir, int lab) { return agentFile(binDir, "raylab-agent-own-lab" + std::to_string(lab)); }

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
    const bool own = !isolated && std::any_of(labs.begin(), labs.end(), [&](int lab) { return fs::exists(ownLabAgent(binDir, lab), error); });
    if (isolated || own) {
        for (int lab : labs) {
            const fs::path program = isolated ? labAgent(binDir, lab) : ownLabAgent(binDir, lab);
            if (fs::exists(program, error)) agents.push_back({program, lab});
        }
    } else if (fs::exists(agentFile(binDir, "raylab-agent"), error)) {
        agents.push_back({agentFile(binDir, "raylab-agent"), 0});
    }
    return agents;
}

std::string labAgentTarget(const fs::path& binDir, int lab) {
    std::error_code error;
    if (fs::exists(labAgent(binDir, lab), error)) return labAgent(binDir, lab).stem().string();
    if (fs::exists(ownLabAgent(binDir, lab), error)) return ownLabAgent(binDir, lab).stem().string();
    return "raylab-agents"; // none built yet: which kind this build makes is CMake's to say
}

namespace {

// Lab `lab` and every lab it uses, directly or through another.
std::vector<int> labClosure(const LabCatalog& course, int lab) {
    std::vector<int> closure{lab};
    for (std::size_t k = 0; k < closure.size(); ++k)
        if (const LabDescription* d = course.lab(closure[k]))
            for (int used : d->uses)
                if (std::find(closure.begin(), closure.end(), used) == closure.end()) closure.push_back(used);
    return closure;
}

// Whether a file of the lab folder `folder` that the compiler reads (.cpp, .h) was written after `since`.
bool compiledFileNewer(const fs::path& folder, fs::file_time_type since) {
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(folder, error)) {
        const std::string extension = entry.path().extension().string();
        if (extension != ".cpp" && extension != ".h" && extension != ".hpp") continue;
        if (entry.path().filename().string().starts_with(".")) continue; // an editor's
        std::error_code unreadable;
        if (entry.is_regular_file(unreadable) && entry.last_write_time(unreadable) > since && !unreadable) return true;
    }
    return false;
}

} // namespace

std::vector<int> labsNotBuilt(const fs::path& binDir, const fs::path& labsDir, const LabCatalog& course,
                              const std::vector<int>& labs, fs::file_time_type tried) {
    bool isolated = false;
    findAgents(binDir, course.numbers(), isolated);
    std::vector<int> notBuilt;
    for (int lab : labs) {
        const fs::path program = isolated ? labAgent(binDir, lab) : ownLabAgent(binDir, lab);
        std::error_code error;
        auto built = fs::last_write_time(program, error);
        if (!error) built = std::max(built, tried);
        // Graded alone, an agent holds its own lab's files only; else those of the labs it uses too.
        const std::vector<int> sources = isolated ? std::vector<int>{lab} : labClosure(course, lab);
        const bool stale = error || std::any_of(sources.begin(), sources.end(), [&](int source) {
                               const LabDescription* d = course.lab(source);
                               return d != nullptr && compiledFileNewer(labsDir / d->id, built);
                           });
        if (stale) notBuilt.push_back(lab);
    }
    return notBuilt;
}

std::unique_ptr<FileLock> lockBuildFolder(const fs::path& buildDir) {
    std::error_code error;
    fs::create_directories(buildDir, error);
    auto lock = std::make_unique<FileLock>(buildDir / kBuildLockFile);
    if (lock->tryAcquire()) return lock;
    const std::string pid = lock->holder();
    std::printf("%s\n", tr("build.waiting", {{"folder", printablePath(buildDir)}, {"pid", pid.empty() ? "?" : pid}}).c_str());
    std::fflush(stdout);
    lock->acquire();
    return lock;
}

bool buildGradingKit(const Toolchain& tools, const fs::path& sourceDir, const fs::path& buildDir, const fs::path& log) {
    fs::create_directories(buildDir);
    const ProcessOptions keep{.keepOutput = kLogKeptBytes};
    const ProcessResult configured = runProcess(configureCommand(tools, sourceDir, buildDir, "", LabCatalog{}), keep);
    const ProcessResult built =
        configured.succeeded() ? runProcess(buildCommand(tools, buildDir, "raylab-grading-kit"), keep) : ProcessResult{};
    writeFileAtomically(log, logText(configured.kept) + configured.error + logText(built.kept));
    return built.succeeded();
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
    for (int lab : numbers) {
        fs::remove(labAgent(bin, lab), error);
        fs::remove(ownLabAgent(bin, lab), error);
    }
    const std::unique_ptr<FileLock> building = lockBuildFolder(buildDir);
    const std::vector<std::string> configure =
        configureCommand(tools, sourceDir, buildDir, cmakeSafe(labs, buildDir).generic_string(), course);
    std::vector<std::string> build = buildCommand(tools, buildDir, "raylab-submission-agents");
    if (tools.generator.find("Ninja") != std::string::npos) build.insert(build.end(), {"--", "-k", "0"});
    else if (tools.generator.find("Makefiles") != std::string::npos) build.insert(build.end(), {"--", "-k"});
    const ProcessOptions keep{.keepOutput = kLogKeptBytes};
    const ProcessResult configured = runProcess(configure, keep);
    if (!configured.succeeded()) {
        writeFileAtomically(b.log, logText(configured.kept) + configured.error);
        requireRoom(configured.kept, buildDir);
        b.compilerMessage = configured.started ? buildProblem(configured.kept) : configured.error;
        b.brokenLabs = numbers;
        return b;
    }
    // What no student changes first (nothing to do in a class, whose kit is built), so that the
    // build's deadline is the student's files' alone; a failure there shows in the build below.
    const ProcessResult kit = runProcess(buildCommand(tools, buildDir, "raylab-grading-kit"), keep);
    ProcessOptions toBuild = keep;
    toBuild.environment = {"RAYLAB_BUILD_DEADLINE=" + std::to_string(std::time(nullptr) + kBuildSeconds)};
    const ProcessResult built = runProcess(build, toBuild);
    writeFileAtomically(b.log, logText(configured.kept) + logText(kit.kept) + logText(built.kept) + built.error);
    if (!built.succeeded()) {
        requireRoom(built.kept, buildDir);
        b.compilerMessage = built.started ? buildProblem(built.kept) : built.error;
    }
    b.isolated = fs::is_directory(sourceDir / "solutions", error);
    if (b.isolated) {
        for (int lab : numbers) {
            const fs::path program = labAgent(bin, lab);
            if (usableProgram(program, b)) b.agents.push_back({program, lab});
            else b.brokenLabs.push_back(lab);
        }
    } else if (usableProgram(agentFile(bin, "raylab-agent"), b)) {
        b.agents.push_back({agentFile(bin, "raylab-agent"), 0});
    } else {
        // Some lab did not compile: each lab's own agent (the labs it uses from the submission, the
        // others' stubs) grades it when its labs compiled.
        for (int lab : numbers) {
            const fs::path program = ownLabAgent(bin, lab);
            if (usableProgram(program, b)) b.agents.push_back({program, lab});
            else b.brokenLabs.push_back(lab);
        }
    }
    return b;
}

} // namespace raylab::grader
