// raylab-build-guard, the compiler launcher of a submission's files: a file that reads outside the
// allowed folders (directly, through `..` or through a symlink) leaves no object and one refusal
// line; an honest file compiles; a compiler that runs past the wall-clock limit is stopped whole.
#include "support/run_program.h"

#include <doctest/doctest.h>

#include <chrono>
#include <fstream>

#ifndef _WIN32

namespace fs = std::filesystem;
using raylab::test::ProgramRun;
using raylab::test::runProgram;

namespace {

struct Folders {
    fs::path root, submission, secret;
    Folders() {
        root = fs::temp_directory_path() / "raylab-guard-test";
        fs::remove_all(root);
        submission = root / "submission";
        secret = root / "solutions";
        fs::create_directories(submission);
        fs::create_directories(secret);
        std::ofstream(secret / "answer.h") << "inline int answer() { return 42; }\n";
        std::ofstream(submission / "own.h") << "inline int own() { return 1; }\n";
    }
    ~Folders() {
        std::error_code ignored;
        fs::remove_all(root, ignored);
    }
    // Compiles submission/<file> through the guard, which allows the submission folder only (and no
    // system header: -nostdinc).
    ProgramRun compile(const std::string& file, const std::string& body) const {
        std::ofstream(submission / file) << body;
        return runProgram({(fs::path(RAYLAB_GRADING_BIN) / "raylab-build-guard").string(), "--allow", submission.string(),
                           "--", RAYLAB_CXX_COMPILER, "-nostdinc", "-MD", "-MF", (root / "file.d").string(), "-c",
                           (submission / file).string(), "-o", (root / "file.o").string()},
                          root / "output.txt");
    }
    bool objectExists() const { return fs::exists(root / "file.o"); }
};

} // namespace

TEST_SUITE("build guard") {

TEST_CASE("a file that includes only its own folder's files compiles") {
    const Folders f;
    const ProgramRun run = f.compile("honest.cpp", "#include \"own.h\"\nint f() { return own(); }\n");
    CHECK_MESSAGE(run.status == 0, run.output);
    CHECK(f.objectExists());
}

TEST_CASE("including a file outside the allowed folders is refused, through .., an absolute path or a symlink") {
    const Folders f;
    fs::create_symlink(f.secret / "answer.h", f.submission / "link.h");
    for (const std::string& include :
         {std::string("../solutions/answer.h"), (f.secret / "answer.h").string(), std::string("link.h")}) {
        CAPTURE(include);
        const ProgramRun run = f.compile("sneaky.cpp", "#include \"" + include + "\"\nint f() { return answer(); }\n");
        CHECK(run.status == 1);
        CHECK_MESSAGE(run.output.find("raylab-build-guard: outside: ") != std::string::npos, run.output);
        CHECK(run.output.find(fs::canonical(f.secret / "answer.h").string()) != std::string::npos);
        CHECK_FALSE(f.objectExists());
    }
}

TEST_CASE("a compile error stays the compiler's: its status, no refusal line") {
    const Folders f;
    const ProgramRun run = f.compile("broken.cpp", "not C++ at all\n");
    CHECK(run.status != 0);
    CHECK(run.output.find("raylab-build-guard") == std::string::npos);
}

TEST_CASE("a compiler that runs past the wall-clock limit is stopped with its process group") {
    const Folders f;
    const auto start = std::chrono::steady_clock::now();
    // A stand-in "compiler" that never ends: sleep.
    const ProgramRun run = runProgram({(fs::path(RAYLAB_GRADING_BIN) / "raylab-build-guard").string(), "--wall-seconds",
                                       "1", "--", "sleep", "60"},
                                      f.root / "output.txt");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(run.status == 1);
    CHECK_MESSAGE(run.output.find("raylab-build-guard: stopped: sleep") != std::string::npos, run.output);
    CHECK(seconds < 30.); // far below the sleep's 60 s: it was killed, not waited for
}

} // TEST_SUITE

#endif
