#include "grader/submission.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace raylab::grader {

namespace fs = std::filesystem;

namespace {

fs::path agentFile(const fs::path& binDir, const std::string& name) {
#ifdef _WIN32
    return binDir / (name + ".exe");
#else
    return binDir / name;
#endif
}

std::string quote(const fs::path& p) {
    std::string quoted(1, '"');
    quoted += p.string();
    quoted += '"';
    return quoted;
}

// The lines that say what went wrong, not the whole log.
std::string errorLines(const fs::path& log) {
    std::ifstream in(log);
    std::string all, errors;
    int count = 0;
    for (std::string line; std::getline(in, line);) {
        all += line + "\n";
        const bool error = line.find("error") != std::string::npos || line.find("Error") != std::string::npos;
        if (error && errors.find(line + "\n") == std::string::npos && count++ < 40) errors += line + "\n"; // once each
    }
    if (!errors.empty()) return errors;
    if (all.size() > 3000) all.erase(0, all.size() - 3000).insert(0, "...");
    return all;
}

// The agent of one lab, built with the other labs from the reference (framework/grader/CMakeLists.txt).
fs::path labAgent(const fs::path& binDir, int lab) { return agentFile(binDir, "raylab-agent-lab" + std::to_string(lab)); }

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

fs::path submissionLabsFolder(const fs::path& submission) {
    std::error_code error;
    return fs::is_directory(submission / "labs", error) ? submission / "labs" : submission;
}

SubmissionBuild buildSubmission(const Toolchain& tools, const fs::path& sourceDir, const fs::path& labs,
                                const fs::path& buildDir, const std::vector<int>& numbers) {
    SubmissionBuild b;
    fs::create_directories(buildDir);
    b.log = fs::absolute(buildDir / "build.log");
    const fs::path bin = buildDir / "bin";
    // A build folder serves a whole class: the last student's agents must not pass for these.
    std::error_code error;
    fs::remove(agentFile(bin, "raylab-agent"), error);
    for (int lab : numbers) fs::remove(labAgent(bin, lab), error);
    std::string configure = quote(tools.cmake) + " -S " + quote(sourceDir) + " -B " + quote(buildDir) +
                            " -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF -DRAYLAB_SUBMISSION_DIR=" +
                            quote(fs::absolute(labs));
    if (!tools.generator.empty() && !fs::exists(buildDir / "CMakeCache.txt", error))
        configure += " -G " + quote(tools.generator);
    const bool ninja = tools.generator.find("Ninja") != std::string::npos;
    const std::string build = quote(tools.cmake) + " --build " + quote(buildDir) + " --target raylab-agents -j 2" +
                              (ninja ? " -- -k 0" : tools.generator.find("Makefiles") != std::string::npos ? " -- -k" : "");
    const std::string redirect = " >> " + quote(b.log) + " 2>&1";
    fs::remove(b.log, error);
    if (std::system((configure + redirect).c_str()) != 0) {
        b.compilerMessage = errorLines(b.log);
        b.brokenLabs = numbers;
        return b;
    }
    const int status = std::system((build + redirect).c_str());
    if (status != 0) b.compilerMessage = errorLines(b.log);
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
        b.brokenLabs = numbers;
    }
    return b;
}

} // namespace raylab::grader
