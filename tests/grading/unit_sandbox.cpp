// The sandbox keeps the parent in charge: limits, timeouts, the channel, the scratch folder.
#include "grader/sandbox.h"

#include <doctest/doctest.h>

#include <chrono>
#include <filesystem>

using namespace raylab::grader;
namespace fs = std::filesystem;

#if defined(__unix__) || defined(__APPLE__)

namespace {

const fs::path kProbe = fs::path(RAYLAB_GRADING_BIN) / "sandbox_probe";

AgentRun probe(const std::string& mode, SandboxLimits limits = {}) {
    const fs::path scratch = fs::temp_directory_path() / ("raylab-sandbox-test-" + mode);
    fs::remove_all(scratch);
    return runAgent(kProbe, {mode}, scratch, limits);
}

bool hasLine(const AgentRun& run, const std::string& text) {
    for (const std::string& line : run.lines)
        if (line.find(text) != std::string::npos) return true;
    return false;
}

double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

} // namespace

TEST_SUITE("sandbox") {

TEST_CASE("results come through the channel, never from stdout") {
    const AgentRun run = probe("report");
    CHECK(run.exitCode == 0);
    REQUIRE(run.lines.size() == 2); // the probe's fake "done" on stdout is not among them
    CHECK(run.lines[0] == R"({"kind":"hello"})");
}

TEST_CASE("an endless loop is stopped at the wall-clock limit, its results kept") {
    SandboxLimits limits;
    limits.wallSeconds = 1.;
    const auto start = std::chrono::steady_clock::now();
    const AgentRun run = probe("loop", limits);
    CHECK(run.timedOut);
    CHECK(hasLine(run, "hello"));
    CHECK(seconds(start) < 5.);
    CHECK(run.describe().find("time limit") != std::string::npos);
}

TEST_CASE("the CPU limit stops a busy loop even without a wall-clock limit") {
    SandboxLimits limits;
    limits.cpuSeconds = 1;
    limits.wallSeconds = 20.;
    const auto start = std::chrono::steady_clock::now();
    const AgentRun run = probe("loop", limits);
    CHECK_FALSE(run.timedOut);
    CHECK(run.signal != 0);
    CHECK(seconds(start) < 10.);
}

TEST_CASE("a child that closes the channel and lives on is stopped") {
    SandboxLimits limits;
    limits.wallSeconds = 1.;
    const AgentRun run = probe("silent", limits);
    CHECK(run.timedOut);
}

TEST_CASE("a grandchild holding the channel open is stopped with its process group") {
    SandboxLimits limits;
    limits.wallSeconds = 1.;
    const auto start = std::chrono::steady_clock::now();
    const AgentRun run = probe("grandchild", limits);
    CHECK(hasLine(run, "hello"));
    CHECK(seconds(start) < 5.);
}

TEST_CASE("a crash is reported as a crash") {
    const AgentRun run = probe("crash");
    CHECK(run.signal != 0);
    CHECK(hasLine(run, "hello"));
    CHECK(run.describe().find("crashed") != std::string::npos);
}

TEST_CASE("output beyond the file size limit stops the child") {
    SandboxLimits limits;
    limits.fileBytes = 1 << 20;
    const AgentRun run = probe("spam", limits);
    CHECK(run.signal != 0);
    CHECK(fs::file_size(fs::temp_directory_path() / "raylab-sandbox-test-spam" / "stdout.txt") <= (1u << 20));
}

TEST_CASE("memory beyond the limit is refused to the child") {
    SandboxLimits limits;
    limits.memoryBytes = 512ull << 20;
    const AgentRun run = probe("alloc", limits);
    CHECK(hasLine(run, "refused"));
}

TEST_CASE("the child runs in its own scratch folder") {
    const AgentRun run = probe("cwd");
    CHECK(hasLine(run, "raylab-sandbox-test-cwd"));
}

} // TEST_SUITE

#endif
