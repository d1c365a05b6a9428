// The sandbox keeps the parent in charge: limits, timeouts, the channel, the scratch folder, and
// (a fake student trying each) no signal to the grader, no process left behind, no network, no
// file outside its scratch folder. Each test runs with bubblewrap and without it (the process-group
// sandbox), except those only bubblewrap promises, which say so when it is missing.
#include "grader/sandbox/sandbox.h"
#include "support/files.h"

#include <doctest/doctest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <thread>

using namespace raylab::grader;
namespace fs = std::filesystem;

#if defined(__SANITIZE_ADDRESS__)
#define RAYLAB_ASAN_TEST 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RAYLAB_ASAN_TEST 1
#endif
#endif

#if defined(__unix__) || defined(__APPLE__)

#include <arpa/inet.h>
#include <csignal>
#include <cstdlib>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace {

const fs::path kProbe = fs::path(RAYLAB_GRADING_BIN) / "sandbox_probe";

bool haveBubblewrap() { return sandboxKind(SandboxLimits{}) == "bubblewrap"; }

// The sandboxes this system has: the process group always, bubblewrap when installed.
std::vector<bool> sandboxes() {
    if (haveBubblewrap()) return {false, true};
    MESSAGE("bubblewrap is not installed: only the process-group sandbox is tested");
    return {false};
}

fs::path scratchFor(const std::string& mode, bool bubblewrap) {
    return raylab::test::scratchPath("raylab-sandbox-test-" + mode + (bubblewrap ? "-bwrap" : "-group"));
}

AgentRun probe(const std::string& mode, bool bubblewrap, SandboxLimits limits = {}, std::vector<std::string> args = {},
               const std::string& requests = "") {
    const fs::path scratch = scratchFor(mode, bubblewrap);
    fs::remove_all(scratch);
    limits.bubblewrap = bubblewrap;
    args.insert(args.begin(), mode);
    return runAgent({kProbe, args, scratch, {}, {}, requests}, limits);
}

bool hasLine(const AgentRun& run, const std::string& text) {
    for (const std::string& line : run.lines)
        if (line.find(text) != std::string::npos) return true;
    return false;
}

// The timing bounds tell a grader that stops at once from one that waits for the item's limit: the
// limit is kItemLimit and a run must end well before it, with room for a loaded machine (a sanitizer
// build, other tests running) rather than a measure of speed.
constexpr double kItemLimit = 120.;
constexpr double kWellBefore = 20.;

double secondsSince(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

std::uintmax_t sizeOf(const fs::path& file) {
    std::error_code error;
    const std::uintmax_t size = fs::file_size(file, error);
    return error ? 0 : size;
}

// True when `file` (a probe's heartbeat) stops growing: what wrote it is gone.
// Its first megabyte (/dev/zero has no end).
std::string readAll(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::string text(1 << 20, '\0');
    in.read(text.data(), std::streamsize(text.size()));
    text.resize(std::size_t(in.gcount()));
    return text;
}

// Whether anything the grader keeps of `run` holds one of the lines of `secret` (20 characters or more).
bool leaks(const AgentRun& run, const std::string& secret) {
    std::istringstream lines(secret);
    for (std::string line; std::getline(lines, line);) {
        if (line.size() < 20) continue;
        if (run.stderrTail.find(line) != std::string::npos || run.describe().find(line) != std::string::npos) return true;
        for (const std::string& l : run.lines)
            if (l.find(line) != std::string::npos) return true;
    }
    return false;
}

bool violated(const AgentRun& run, const std::string& file) {
    for (const std::string& v : run.violations)
        if (v.find("replaced its output file " + file) != std::string::npos) return true;
    return false;
}

bool heartbeatStopped(const fs::path& file) {
    const std::uintmax_t before = sizeOf(file);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    return sizeOf(file) == before;
}

} // namespace

TEST_SUITE("sandbox") {

TEST_CASE("results come through the channel, never from stdout") {
    for (bool bwrap : sandboxes()) {
        CAPTURE(bwrap);
        const AgentRun run = probe("report", bwrap);
        CHECK(run.exitCode == 0);
        REQUIRE(run.lines.size() == 2); // the probe's fake "done" on stdout is not among them
        CHECK(run.lines[0] == R"({"kind":"hello"})");
    }
}

TEST_CASE("an endless loop is stopped at the wall-clock limit, its results kept") {
    for (bool bwrap : sandboxes()) {
        CAPTURE(bwrap);
        SandboxLimits limits;
        limits.wallSeconds = 1.;
        limits.totalSeconds = kItemLimit; // what would stop it if the item's limit did not
        const auto start = std::chrono::steady_clock::now();
        const AgentRun run = probe("loop", bwrap, limits);
        CHECK(run.timedOut);
        CHECK(hasLine(run, "hello"));
        CHECK(secondsSince(start) >= 1.);
        CHECK(secondsSince(start) < kWellBefore);
        CHECK(run.describe().find("time limit") != std::string::npos);
    }
}

TEST_CASE("the CPU limit stops a busy loop even without a wall-clock limit") {
    for (bool bwrap : sandboxes()) {
        CAPTURE(bwrap);
        SandboxLimits limits;
        limits.cpuSeconds = 1;
        limits.wallSeconds = kItemLimit; // a CPU second may take several on a loaded machine
        const AgentRun run = probe("loop", bwrap, limits);
        CHECK_FALSE(run.timedOut);
        CHECK(run.signal == SIGXCPU);
    }
}

TEST_CASE("a child that closes its channel and lives on is stopped long before the item's limit") {
    for (bool bwrap : sandboxes())
        for (const char* mode : {"silent", "close-and-loop"}) {
            CAPTURE(bwrap);
            CAPTURE(mode);
            SandboxLimits limits;
            limits.wallSeconds = kItemLimit;
            const auto start = std::chrono::steady_clock::now();
            const AgentRun run = probe(mode, bwrap, limits);
            CHECK(run.timedOut);
            CHECK(secondsSince(start) < kWellBefore);
        }
}

TEST_CASE("a grandchild holding the channel open does not hold the grader: the run ends with the child") {
    for (bool bwrap : sandboxes()) {
        CAPTURE(bwrap);
        SandboxLimits limits;
        limits.wallSeconds = kItemLimit;
        const auto start = std::chrono::steady_clock::now();
        const AgentRun run = probe("grandchild", bwrap, limits);
        CHECK(hasLine(run, "hello"));
        CHECK(run.exitCode == 0);
        CHECK(secondsSince(start) < kWellBefore);
    }
}

TEST_CASE("20 busy children are all stopped when their parent exits") {
    for (bool bwrap : sandboxes()) {
        CAPTURE(bwrap);
        SandboxLimits limits;
        limits.wallSeconds = kItemLimit;
        const auto start = std::chrono::steady_clock::now();
        const AgentRun run = probe("busy-children", bwrap, limits);
        CHECK(hasLine(run, "hello"));
        CHECK(secondsSince(start) < kWellBefore);
        CHECK(heartbeatStopped(scratchFor("busy-children", bwrap) / "heartbeat"));
    }
}

TEST_CASE("a setsid daemon does not outlive the run") {
    for (bool bwrap : sandboxes()) {
        CAPTURE(bwrap);
        SandboxLimits limits;
        limits.wallSeconds = kItemLimit;
        const auto start = std::chrono::steady_clock::now();
        const AgentRun run = probe("daemon", bwrap, limits);
        CHECK(hasLine(run, "hello"));
        CHECK(secondsSince(start) < kWellBefore);
        const fs::path heartbeat = scratchFor("daemon", bwrap) / "heartbeat";
        CHECK(sizeOf(heartbeat) > 0); // it ran
        CHECK(heartbeatStopped(heartbeat));
    }
}

TEST_CASE("a SIGTERM to the grader does not end it: without bubblewrap it is recorded, with it it cannot reach") {
    struct sigaction before{};
    sigaction(SIGTERM, nullptr, &before);
    for (bool bwrap : sandboxes()) {
        CAPTURE(bwrap);
        const AgentRun run = probe("signal-grader", bwrap, {}, {std::to_string(getpid())});
        REQUIRE(hasLine(run, "signalled")); // and the grader is still here
        if (bwrap) {
            CHECK(hasLine(run, R"("grader":-1)")); // no such process in its namespace
            CHECK(run.violations.empty());
        } else {
            REQUIRE(!run.violations.empty()); // two signals, which may arrive as one
            CHECK(run.violations[0].find("sent signal 15") != std::string::npos);
            CHECK(run.describe().find("sent signal 15") != std::string::npos);
        }
    }
    struct sigaction after{};
    sigaction(SIGTERM, nullptr, &after);
    CHECK(reinterpret_cast<void*>(after.sa_handler) == reinterpret_cast<void*>(before.sa_handler)); // the grader's own handling is back
}

TEST_CASE("the grader's environment is not the child's") {
    setenv("RAYLAB_TEST_SECRET", "1", 1);
    for (bool bwrap : sandboxes()) {
        CAPTURE(bwrap);
        const AgentRun run = probe("environment", bwrap);
        REQUIRE(hasLine(run, "environment"));
        CHECK(hasLine(run, R"("secret":"")"));
    }
    unsetenv("RAYLAB_TEST_SECRET");
}

TEST_CASE("requests go to the child on a second pipe, more than a pipe holds, without blocking the parent") {
    for (bool bwrap : sandboxes()) {
        CAPTURE(bwrap);
        std::string requests;
        for (int k = 0; k < 20000; ++k) requests += "request number " + std::to_string(k) + "\n"; // about 400 kB
        SandboxLimits limits;
        limits.wallSeconds = 10.;
        const AgentRun run = probe("echo-requests", bwrap, limits, {}, requests);
        REQUIRE(run.lines.size() == 20001);
        CHECK(run.lines[0] == R"({"kind":"echo","text":"request number 0"})");
        CHECK(run.lines[19999] == R"({"kind":"echo","text":"request number 19999"})");
        CHECK(run.lines[20000] == R"({"kind":"done"})");
        CHECK_FALSE(run.timedOut);
    }
}

TEST_CASE("bubblewrap: no network, not even to a listener on 127.0.0.1") {
    if (!haveBubblewrap()) {
        MESSAGE("SKIPPED: bubblewrap is not installed (apt install bubblewrap)");
        return;
    }
    const int listener = socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK, 0);
    REQUIRE(listener >= 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    REQUIRE(bind(listener, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0);
    REQUIRE(listen(listener, 4) == 0);
    socklen_t length = sizeof address;
    getsockname(listener, reinterpret_cast<sockaddr*>(&address), &length);
    const AgentRun run = probe("connect", true, {}, {std::to_string(ntohs(address.sin_port))});
    CHECK(hasLine(run, R"("connected":false)"));
    CHECK(accept(listener, nullptr, nullptr) < 0); // nothing arrived
    close(listener);
    // The same probe without bubblewrap does connect: the test above sees what it claims to.
    const AgentRun open = [&] {
        const int again = socket(AF_INET, SOCK_STREAM, 0);
        sockaddr_in any{};
        any.sin_family = AF_INET;
        any.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        bind(again, reinterpret_cast<sockaddr*>(&any), sizeof any);
        listen(again, 4);
        socklen_t size = sizeof any;
        getsockname(again, reinterpret_cast<sockaddr*>(&any), &size);
        const AgentRun r = probe("connect", false, {}, {std::to_string(ntohs(any.sin_port))});
        close(again);
        return r;
    }();
    CHECK(hasLine(open, R"("connected":true)"));
}

TEST_CASE("bubblewrap: nothing outside its scratch folder can be read, written or deleted") {
    if (!haveBubblewrap()) {
        MESSAGE("SKIPPED: bubblewrap is not installed (apt install bubblewrap)");
        return;
    }
    const fs::path root = raylab::test::scratchPath("raylab-sandbox-escape");
    fs::remove_all(root);
    fs::create_directories(root / "sibling");
    fs::create_directories(root / "references");
    std::ofstream(root / "sibling" / "keep.txt") << "another student's work";
    std::ofstream(root / "references" / "lab1_gradient.png") << "the reference picture";
    const AgentRun run = runAgent({kProbe, {"escape", (root / "references" / "lab1_gradient.png").string()},
                                   root / "scratch"},
                                  SandboxLimits{});
    REQUIRE(hasLine(run, "done"));
    CHECK(hasLine(run, R"("bytes":0)")); // the references are not there
    CHECK(fs::exists(root / "sibling" / "keep.txt"));
    CHECK(fs::exists(root / "references" / "lab1_gradient.png"));
    CHECK_FALSE(fs::exists(root / "intruder.txt"));
    fs::remove_all(root);
}

TEST_CASE("a stderr.txt replaced with a link is not followed: the run is an attack, and no byte of the target is read") {
    const fs::path solution = fs::path(RAYLAB_SOURCE_DIR) / "solutions" / "lab3_sphere" / "sphere_geometry.cpp";
    REQUIRE(readAll(solution).size() > 100);
    std::vector<fs::path> targets{solution, "/dev/zero"}; // /dev/zero would grow the grader without end
    if (readAll("/etc/shadow").size() > 0) targets.push_back("/etc/shadow");
    for (bool bwrap : sandboxes())
        for (const fs::path& target : targets) {
            CAPTURE(bwrap);
            CAPTURE(target);
            const AgentRun run = probe("replace-stderr", bwrap, {}, {"symlink:" + target.string()});
            REQUIRE(hasLine(run, R"("made":0)"));
            CHECK(violated(run, "stderr.txt"));
            CHECK(run.describe().find("replaced its output file stderr.txt") != std::string::npos);
            CHECK(run.stderrTail.empty());
            CHECK_FALSE(leaks(run, readAll(target)));
            CHECK(fs::is_symlink(scratchFor("replace-stderr", bwrap) / "stderr.txt")); // left as it was, unread
        }
}

TEST_CASE("a stderr.txt replaced with a FIFO does not block the grader: the run is an attack") {
    for (bool bwrap : sandboxes()) {
        CAPTURE(bwrap);
        const AgentRun run = probe("replace-stderr", bwrap, {}, {"fifo"}); // a read of it would wait for ever
        REQUIRE(hasLine(run, R"("made":0)"));
        CHECK(violated(run, "stderr.txt"));
    }
}

TEST_CASE("without bubblewrap, a stderr.txt hard-linked to a file of the grader's is neither read nor cut") {
    const fs::path secret = raylab::test::scratchPath("raylab-sandbox-test-secret.txt");
    std::string text;
    for (int k = 0; k < 4000; ++k) text += "secret line number " + std::to_string(k) + " of the grader's\n"; // > the kept size
    std::ofstream(secret, std::ios::binary) << text;
    const AgentRun run = probe("replace-stderr", false, {}, {"hardlink:" + secret.string()});
    REQUIRE(hasLine(run, R"("made":0)"));
    CHECK(violated(run, "stderr.txt"));
    CHECK_FALSE(leaks(run, text));
    CHECK(readAll(secret) == text); // not cut down to the kept size
    fs::remove(scratchFor("replace-stderr", false) / "stderr.txt");
    fs::remove(secret);
}

TEST_CASE("an honest error output is read back for the report") {
    for (bool bwrap : sandboxes()) {
        CAPTURE(bwrap);
        const AgentRun run = probe("replace-stderr", bwrap, {}, {"keep"});
        CHECK(run.violations.empty());
        CHECK(run.exitCode == 1);
        CHECK(run.stderrTail == "an honest line of error output\n");
    }
}

TEST_CASE("a crash is reported as a crash") {
    for (bool bwrap : sandboxes()) {
        CAPTURE(bwrap);
        const AgentRun run = probe("crash", bwrap);
        CHECK(run.signal == SIGSEGV);
        CHECK(hasLine(run, "hello"));
        CHECK(run.describe().find("crashed") != std::string::npos);
    }
}

TEST_CASE("output beyond the file size limit stops the child") {
    for (bool bwrap : sandboxes()) {
        CAPTURE(bwrap);
        SandboxLimits limits;
        limits.fileBytes = 1 << 20;
        const AgentRun run = probe("spam", bwrap, limits);
        CHECK(run.signal == SIGXFSZ);
        // Cut down to what a run keeps, on disk too: the spam does not stay in the grader's folders.
        CHECK(fs::file_size(scratchFor("spam", bwrap) / "stdout.txt") == kOutputKeptBytes);
    }
}

TEST_CASE("memory beyond the limit is refused to the child") {
    for (bool bwrap : sandboxes()) {
        CAPTURE(bwrap);
        SandboxLimits limits;
        limits.memoryBytes = 512ull << 20;
        limits.wallSeconds = 20.;
        const AgentRun run = probe("alloc", bwrap, limits);
#ifdef RAYLAB_ASAN_TEST
        // No address-space limit here: the run's cgroup stops all its processes at memoryBytes, where the
        // machine gives one (the run then says so); else ASan's own RSS limit, set from memoryBytes,
        // stops the child and says why (in stderr.txt, before the memory map it prints).
        std::ifstream errors(scratchFor("alloc", bwrap) / "stderr.txt");
        const std::string said{std::istreambuf_iterator<char>(errors), std::istreambuf_iterator<char>()};
        if (run.memoryLimit) {
            CHECK_MESSAGE(run.describe().find("512 MB of memory") != std::string::npos, run.describe());
        } else {
            CHECK(run.exitCode > 0);
            CHECK_MESSAGE(said.find("hard rss limit exhausted (512Mb") != std::string::npos, run.describe());
        }
        CHECK_FALSE(run.timedOut);
#else
        CHECK(hasLine(run, "refused"));
#endif
    }
}

TEST_CASE("the child runs in its own scratch folder") {
    for (bool bwrap : sandboxes()) {
        CAPTURE(bwrap);
        const AgentRun run = probe("cwd", bwrap);
        CHECK(hasLine(run, scratchFor("cwd", bwrap).filename().string()));
    }
}

} // TEST_SUITE

#endif
