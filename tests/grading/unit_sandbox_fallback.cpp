// The sandbox where bubblewrap cannot start and the grader is root (sandbox/unprivileged.h), forced
// with RAYLAB_SANDBOX=fallback on a machine that has bubblewrap: the agent runs as another user, in
// a scratch folder of its own, from a copy of its program; it cannot take root back, write the grader's
// folders, read a file only root can read, or run another program of its folder; with libseccomp, it
// opens no network socket and reads no process's memory; with Landlock, it opens no file it was not given.
// Each test also runs the probe in the process group (as root), which does all of it: the probe
// sees what the test claims.
#include "grader/sandbox/compile_stage.h"
#include "grader/sandbox/landlock.h"
#include "grader/sandbox/unprivileged.h"
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

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
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
    if (sandboxKind(SandboxLimits{}).find("no seccomp filter") != std::string::npos) {
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

TEST_CASE("a tree in a folder only root may enter (as /root): the agent runs, reads its inputs, and nothing beside") {
    if (skippedUnlessRoot()) return;
    const FallbackForced fallback;
    // home/ as /root is (0700), the build's programs and the scenes in it, as the grader's tree would be.
    const fs::path home = raylab::test::freshFolder("raylab-fallback-home");
    const fs::path bin = home / "build" / "bin", scenes = home / "scenes";
    fs::create_directories(bin);
    fs::create_directories(scenes);
    fs::copy_file(kProbe, bin / "raylab-agent-lab1");
    fs::copy_file(kProbe, bin / "raylab-agent-reference");
    std::ofstream(scenes / "figure.toml") << "its input";
    std::ofstream(home / "solution.cpp") << "what it must not read";
    fs::permissions(home, fs::perms::owner_all);
    const std::string requests = "{\"sceneFile\":\"" + (scenes / "figure.toml").string() + "\"}\n";
    const auto reach = [&](bool sandboxAllowed) {
        SandboxLimits limits;
        limits.bubblewrap = sandboxAllowed;
        limits.wallSeconds = 20.;
        const AgentRun run = runAgent({bin / "raylab-agent-lab1",
                                       {"reach", (home / "solution.cpp").string(), (bin / "raylab-agent-reference").string()},
                                       home / "scratch",
                                       {scenes},
                                       {},
                                       requests},
                                      limits);
        for (const std::string& line : run.lines)
            if (line.find("\"reach\"") != std::string::npos) return nlohmann::json::parse(line);
        FAIL("the probe did not report: " << run.describe() << " " << run.stderrTail);
        return nlohmann::json{};
    };
    const nlohmann::json confined = reach(true);
    CHECK(confined["input"] == "its input"); // its scene, through its copy
    CHECK(confined["sibling"] == false);     // a file of the tree beside it
    CHECK(confined["ran"] == false);         // the reference's program beside it
    const nlohmann::json open = reach(false); // root's process group: every one of them is there
    CHECK(open["input"] == "its input");
    CHECK(open["sibling"] == true);
    CHECK(open["ran"] == true);
    fs::remove_all(home);
}

TEST_CASE("an agent's stage is a folder of /tmp of its own, and nothing of it stays once it goes") {
    if (!detail::unprivilegedUser()) {
        MESSAGE("SKIPPED: only root has the fallback's user");
        return;
    }
    fs::path folder;
    {
        const detail::AgentStage stage(kProbe, {});
        folder = stage.program().parent_path();
        CHECK(folder.parent_path() == "/tmp");
        CHECK(fs::exists(stage.program()));
    }
    CHECK_FALSE(fs::exists(folder)); // the stage's own: nothing left for a process ending with _exit to leave
}

TEST_CASE("the compiler's stage: copies of the allowed folders alone, their paths put back in its words even cut "
          "between two reads") {
    if (!detail::unprivilegedUser()) {
        MESSAGE("SKIPPED: only root has the fallback's user");
        return;
    }
    const fs::path root = raylab::test::freshFolder("raylab-compile-stage-test");
    fs::create_directories(root / "allowed" / "inner");
    fs::create_directories(root / "beside");
    std::ofstream(root / "allowed" / "inner" / "kept.h") << "kept";
    std::ofstream(root / "beside" / "secret.h") << "secret";
    fs::create_symlink(root / "beside" / "secret.h", root / "allowed" / "link.h");
    detail::CompileStage stage({root / "allowed", root / "allowed" / "inner", "/usr/include"}, *detail::unprivilegedUser());
    const std::optional<fs::path> kept = stage.copyOf(root / "allowed" / "inner" / "kept.h");
    REQUIRE(kept);
    CHECK(raylab::test::readFile(*kept) == "kept");
    CHECK_FALSE(fs::exists(kept->parent_path().parent_path() / "link.h")); // links left out
    CHECK_FALSE(stage.copyOf(root / "beside" / "secret.h"));
    CHECK_FALSE(stage.copyOf("/usr/include/stdio.h")); // the system's, read where they are
    CHECK(std::find(stage.readable().begin(), stage.readable().end(), "/usr/include") != stage.readable().end());
    struct stat copy {};
    REQUIRE(stat(kept->c_str(), &copy) == 0);
    CHECK(copy.st_uid == 0);
    CHECK((copy.st_mode & 0777) == 0444);
    // The compiler's error line, passed on in two reads cut anywhere: the original path each time.
    const std::string said = kept->string() + ":1:1: error: x\n", meant = (root / "allowed/inner/kept.h").string() + ":1:1: error: x\n";
    CHECK(stage.original(said) == meant);
    for (std::size_t cut = 0; cut <= said.size(); ++cut) {
        CAPTURE(cut);
        std::string passed = stage.originalPart(std::string_view(said).substr(0, cut));
        passed += stage.originalPart(std::string_view(said).substr(cut));
        passed += stage.originalPart({}, true);
        CHECK(passed == meant);
    }
    fs::remove_all(root);
}

TEST_CASE("with Landlock, a world-readable file it was not given cannot be opened") {
    if (skippedUnlessRoot()) return;
    if (detail::landlockAbi() == 0) {
        MESSAGE("SKIPPED: this kernel has no Landlock");
        return;
    }
    const FallbackForced fallback;
    const GraderFolders folders;
    const fs::path open = folders.root / "open" / "notes.txt"; // anyone may read it, without Landlock
    fs::create_directories(open.parent_path());
    std::ofstream(open) << "a classmate's file";
    fs::permissions(folders.root, fs::perms(0755));
    fs::permissions(open.parent_path(), fs::perms(0755));
    fs::permissions(open, fs::perms(0644));
    fs::remove_all(folders.scratch);
    const AgentRun run = runAgent({kProbe, {"privileges", open.string(), folders.results.string()}, folders.scratch}, SandboxLimits{});
    nlohmann::json said;
    for (const std::string& line : run.lines)
        if (line.find("\"privileges\"") != std::string::npos) said = nlohmann::json::parse(line);
    REQUIRE_MESSAGE(!said.is_null(), run.describe() << " " << run.stderrTail);
    CHECK(said["read"] == false);
    CHECK(sandboxKind(SandboxLimits{}).find("no Landlock") == std::string::npos);
}

TEST_CASE("a Landlock ruleset: a file of an allowed folder opens, one beside it does not") {
    if (detail::landlockAbi() == 0) {
        MESSAGE("SKIPPED: this kernel has no Landlock");
        return;
    }
    const fs::path root = raylab::test::freshFolder("raylab-landlock");
    fs::create_directories(root / "allowed");
    std::ofstream(root / "allowed" / "in.txt") << "in";
    std::ofstream(root / "outside.txt") << "out";
    detail::LandlockRules rules = detail::systemRules();
    rules.read.push_back(root / "allowed");
    const detail::LandlockRuleset ruleset(rules);
    const pid_t child = fork(); // the restriction is for good: a child of the test's takes it
    REQUIRE(child >= 0);
    if (child == 0) {
        if (!detail::restrictSelf(ruleset.fd())) _exit(10);
        const bool in = open((root / "allowed" / "in.txt").c_str(), O_RDONLY) >= 0;
        const bool out = open((root / "outside.txt").c_str(), O_RDONLY) >= 0;
        const bool written = open((root / "allowed" / "new.txt").c_str(), O_WRONLY | O_CREAT, 0644) >= 0;
        _exit((in ? 0 : 1) | (out ? 2 : 0) | (written ? 4 : 0));
    }
    int status = 0;
    REQUIRE(waitpid(child, &status, 0) == child);
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0); // the allowed file read; nothing outside read; nothing written
    CHECK(fs::exists(root / "outside.txt"));
    fs::remove_all(root);
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
