// runProcess: an argument vector, never a shell, so an argument reaches the program as it is; a
// program past its time limit is killed rather than waited for. POSIX programs (printf, sleep).
#include "grader/sandbox/process.h"
#include "support/files.h"

#include <doctest/doctest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <sys/resource.h>

using namespace raylab::grader;
namespace fs = std::filesystem;

#if defined(__unix__) || defined(__APPLE__)

namespace {

// The most memory this process has held so far, in bytes.
long peakMemory() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
#ifdef __APPLE__
    return usage.ru_maxrss; // bytes
#else
    return usage.ru_maxrss * 1024L; // kilobytes
#endif
}

} // namespace

TEST_SUITE("process") {

TEST_CASE("an argument with spaces, quotes and $( ) reaches the program as one argument, nothing run") {
    const fs::path output = fs::temp_directory_path() / ("raylab-process-" + std::to_string(std::random_device{}()));
    const std::string argument = "a b \"c\" 'd' $(echo e) ; f";
    const ProcessResult r = runProcess({"printf", "[%s]", argument}, {{}, output});
    CHECK(r.succeeded());
    std::ifstream in(output, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    CHECK(text.str() == "[" + argument + "]");
    fs::remove(output);
}

TEST_CASE("a program past its time limit is killed within a second of it") {
    const auto start = std::chrono::steady_clock::now();
    const ProcessResult r = runProcess({"sleep", "30"}, {{}, {}, 0.5});
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(r.started);
    CHECK(r.signal == SIGKILL);
    CHECK_FALSE(r.succeeded());
    CHECK(seconds >= 0.5);
    CHECK(seconds < 1.5);
}

TEST_CASE("a program within its time limit ends as it would without one") {
    const ProcessResult r = runProcess({"sleep", "0.1"}, {{}, {}, 20.});
    CHECK(r.succeeded());
    CHECK(r.signal == 0);
}

TEST_CASE("kept output: a short output whole, nothing cut") {
    const ProcessResult r = runProcess({"printf", "line 1\nline 2\n"}, {.keepOutput = 1 << 16});
    CHECK(r.succeeded());
    CHECK(r.kept.head == "line 1\nline 2\n");
    CHECK(r.kept.tail.empty());
    CHECK(r.kept.cut == 0);
}

TEST_CASE("kept output: a long output's first and last 64 KB, byte for byte, and the size of what was cut between") {
    const ProcessResult r = runProcess({"seq", "1", "2000000"}, {.keepOutput = 1 << 16});
    REQUIRE(r.succeeded());
    std::string expected;
    for (int k = 1; k <= 2000000; ++k) expected += std::to_string(k) + "\n";
    CHECK(r.kept.head == expected.substr(0, 1 << 16));
    CHECK(r.kept.tail == expected.substr(expected.size() - (1 << 16)));
    CHECK(r.kept.cut == expected.size() - 2 * (1 << 16));
}

TEST_CASE("kept output: a gigabyte streamed through, never held: 128 KB kept, memory and disk untouched") {
    const long before = peakMemory();
    const ProcessResult r = runProcess({"head", "-c", "1073741824", "/dev/zero"}, {.keepOutput = 1 << 16});
    REQUIRE(r.succeeded());
    CHECK(r.kept.head == std::string(1 << 16, '\0'));
    CHECK(r.kept.tail == std::string(1 << 16, '\0'));
    CHECK(r.kept.cut == (std::uint64_t(1) << 30) - 2 * (1 << 16));
    MESSAGE("peak memory " << before / 1048576 << " MB before, " << peakMemory() / 1048576 << " MB after");
#if defined(__SANITIZE_ADDRESS__)
    // ASan's allocator keeps freed memory in quarantine (256 MB by default): the peak says nothing here.
    MESSAGE("the peak is not checked under ASan");
#else
    CHECK(peakMemory() - before < 64L << 20); // far below the gigabyte
#endif
}

TEST_CASE("kept output: a process left holding the pipe does not hold the wait, nor does a time limit fail to stop") {
    // sh starts a sleeper that inherits the pipe, says its pid and exits: its exit ends the wait.
    const auto start = std::chrono::steady_clock::now();
    const ProcessResult left = runProcess({"sh", "-c", "sleep 600 & echo $!"}, {.keepOutput = 1 << 16});
    CHECK(left.succeeded());
    REQUIRE(!left.kept.head.empty());
    kill(pid_t(std::stol(left.kept.head)), SIGKILL);
    const ProcessResult slow = runProcess({"sleep", "600"}, {.timeLimit = 0.5, .keepOutput = 1 << 16});
    CHECK(slow.signal == SIGKILL);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(seconds < 60.); // far below the sleeps' 600 s: neither was waited for
}

TEST_CASE("argumentPointers: each argument's characters, then a null pointer") {
    std::vector<std::string> args{"raylab", "grade", ""};
    const std::vector<char*> pointers = argumentPointers(args);
    REQUIRE(pointers.size() == 4);
    for (std::size_t k = 0; k < args.size(); ++k) CHECK(pointers[k] == args[k].data());
    CHECK(pointers[3] == nullptr);
}

TEST_CASE("findProgram: the first executable file of that name in PATH, else nothing") {
    const fs::path folder = raylab::test::scratchPath("raylab-find-program");
    fs::remove_all(folder);
    fs::create_directories(folder / "a");
    fs::create_directories(folder / "b");
    std::ofstream(folder / "a" / "tool") << "not executable";
    std::ofstream(folder / "b" / "tool") << "#!/bin/sh\n";
    fs::permissions(folder / "b" / "tool", fs::perms::owner_exec, fs::perm_options::add);
    fs::create_directories(folder / "c" / "tool"); // a folder is not a program
    const char* saved = std::getenv("PATH");
    const std::string path = saved ? saved : "";
    setenv("PATH", ((folder / "c").string() + ":" + (folder / "a").string() + "::" + (folder / "b").string()).c_str(), 1);
    const fs::path found = findProgram("tool"), missing = findProgram("no-such-tool");
    setenv("PATH", path.c_str(), 1);
    CHECK(found == folder / "b" / "tool");
    CHECK(missing.empty());
}

} // TEST_SUITE

#endif
