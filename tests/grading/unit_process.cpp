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

using namespace raylab::grader;
namespace fs = std::filesystem;

#if defined(__unix__) || defined(__APPLE__)

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
