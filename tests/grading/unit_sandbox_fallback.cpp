// The sandbox where bubblewrap cannot start and the grader is root (sandbox/unprivileged.h), forced
// with RAYLAB_SANDBOX=fallback on a machine that has bubblewrap: the agent runs as another user, in
// a scratch folder of its own; it cannot take root back, write the grader's folders or read a file
// only root can read; with libseccomp, it opens no network socket and reads no process's memory.
// Each test also runs the probe in the process group (as root), which does all of it: the probe
// sees what the test claims.
#include "grader/sandbox/sandbox.h"
#include "support/files.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

using namespace raylab::grader;
namespace fs = std::filesystem;

#ifdef __linux__

#include <sys/stat.h>
#include <unistd.h>

namespace {

const fs::path kProbe = fs::path(RAYLAB_GRADING_BIN) / "sandbox_probe";

// RAYLAB_SANDBOX=fallback while it lives (each run reads it), then as it was.
class FallbackForced {
public:
    FallbackForced() {
        if (const char* was = std::getenv("RAYLAB_SANDBOX")) m_was = was;
        setenv("RAYLAB_SANDBOX", "fallback", 1);
    }
    ~FallbackForced() {
        if (m_was) setenv("RAYLAB_SANDBOX", m_was->c_str(), 1);
        else unsetenv("RAYLAB_SANDBOX");
    }
    FallbackForced(const FallbackForced&) = delete;
    FallbackForced& operator=(const FallbackForced&) = delete;

private:
    std::optional<std::string> m_was;
};

// A grader's folders: its results folder (root's, 0755) and a secret in a folder only root can read.
struct GraderFolders {
    fs::path root = raylab::test::scratchPath("raylab-fallback-test");
    fs::path results = root / "results", secret = root / "private" / "secret.txt", scratch = root / "scratch";
    GraderFolders() {
        fs::remove_all(root);
        fs::create_directories(results);
        fs::create_directories(secret.parent_path());
        std::ofstream(secret) << "what only the grader may read\n";
        fs::permissions(secret.parent_path(), fs::perms::owner_all);
        fs::permissions(results, fs::perms(0755));
    }
    ~GraderFolders() { fs::remove_all(root); }
};

// What the probe found it could do (its "privileges" line).
nlohmann::json privileges(const GraderFolders& folders, bool sandboxAllowed) {
    SandboxLimits limits;
    limits.bubblewrap = sandboxAllowed; // false: the process group, `--no-sandbox`
    fs::remove_all(folders.scratch);
    const AgentRun run = runAgent({kProbe, {"privileges", folders.secret.string(), folders.results.string()}, folders.scratch}, limits);
    for (const std::string& line : run.lines)
        if (line.find("\"privileges\"") != std::string::npos) return nlohmann::json::parse(line);
    FAIL("the probe did not report: " << run.describe() << " " << run.stderrTail);
    return {};
}

bool skippedUnlessRoot() {
    if (geteuid() == 0) return false;
    MESSAGE("SKIPPED: only root can run the fallback (its agents run as another user); not root here");
    return true;
}

} // namespace

TEST_SUITE("sandbox fallback") {

TEST_CASE("an agent runs as an unprivileged user: no root, nothing of the grader's written or read") {
    if (skippedUnlessRoot()) return;
    const FallbackForced fallback;
    CHECK(sandboxKind(SandboxLimits{}).rfind("unprivileged user", 0) == 0);
    const GraderFolders folders;
    const nlohmann::json confined = privileges(folders, true);
    CHECK(confined["uid"] != 0);
    CHECK(confined["euid"] != 0);
    CHECK(confined["root"] == false);  // setuid(0) failed: root cannot be taken back
    CHECK(confined["read"] == false);  // the file in root's 0700 folder
    CHECK(confined["wrote"] == false); // the grader's results folder
    CHECK_FALSE(fs::exists(folders.results / "intruder.txt"));
    struct stat scratch {};
    REQUIRE(stat(folders.scratch.c_str(), &scratch) == 0); // its scratch folder: its own, only its own
    CHECK(scratch.st_uid == confined["uid"].get<uid_t>());
    CHECK((scratch.st_mode & 0777) == 0700);

    const nlohmann::json open = privileges(folders, false);
    CHECK(open["uid"] == 0);
    CHECK(open["root"] == true);
    CHECK(open["read"] == true);
    CHECK(open["wrote"] == true);
}

TEST_CASE("its seccomp filter: no AF_INET socket, no process_vm_readv; AF_UNIX still works") {
    if (skippedUnlessRoot()) return;
    const FallbackForced fallback;
    if (sandboxKind(SandboxLimits{}) != "unprivileged user") {
        MESSAGE("SKIPPED: raylab was built without libseccomp (" << sandboxKind(SandboxLimits{}) << ")");
        return;
    }
    const GraderFolders folders;
    const nlohmann::json confined = privileges(folders, true);
    CHECK(confined["inet"] == false);
    CHECK(confined["peeked"] == false);
    CHECK(confined["unix"] == true);
    const nlohmann::json open = privileges(folders, false);
    CHECK(open["inet"] == true);
    CHECK(open["peeked"] == true);
}

TEST_CASE("RAYLAB_SANDBOX and --no-sandbox name the mode the results record") {
    SandboxLimits off;
    off.bubblewrap = false;
    CHECK(sandboxKind(off) == "process group");
    const FallbackForced fallback;
    CHECK(sandboxKind(off) == "process group"); // --no-sandbox wins
    CHECK(sandboxKind(SandboxLimits{}).rfind(geteuid() == 0 ? "unprivileged user" : "process group", 0) == 0);
    setenv("RAYLAB_SANDBOX", "none", 1);
    CHECK(sandboxKind(SandboxLimits{}) == "process group");
}

} // TEST_SUITE

#endif
