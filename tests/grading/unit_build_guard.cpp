// raylab-build-guard, the compiler launcher of a submission's files: under bubblewrap the compiler
// sees only what it was allowed, so a file that reads outside (`#include` directly, through `..` or a
// symlink, the assembler's `.incbin`) does not compile; without it (RAYLAB_SANDBOX=none) the
// dependency file is checked, a second wall: no object and one refusal line. An honest file compiles
// in both; a compiler that runs past the wall-clock limit is stopped whole.
#include "grader/sandbox/landlock.h"
#include "grader/sandbox/sandbox.h"
#include "support/files.h"
#include "support/run_program.h"

#include <doctest/doctest.h>

#include <chrono>
#include <ctime>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>
#include <iterator>
#include <vector>

#ifndef _WIN32

namespace fs = std::filesystem;
using raylab::test::ProgramRun;
using raylab::test::readFile;
using raylab::test::runProgram;

namespace {

struct Folders {
    fs::path root, submission, secret;
    Folders() {
        root = raylab::test::scratchPath("raylab-guard-test");
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
    // system header: -nostdinc); `confined`: under bubblewrap, else with RAYLAB_SANDBOX=none.
    ProgramRun compile(const std::string& file, const std::string& body, bool confined = false) const {
        return compileIn(confined ? "bubblewrap" : "none", file, body);
    }
    // The same with RAYLAB_SANDBOX=`sandbox`.
    ProgramRun compileIn(const std::string& sandbox, const std::string& file, const std::string& body) const {
        std::ofstream(submission / file) << body;
        std::vector<std::string> argv{"/usr/bin/env", "RAYLAB_SANDBOX=" + sandbox,
                                      (fs::path(RAYLAB_GRADING_BIN) / "raylab-build-guard").string(),
                                      "--allow", submission.string(), "--", RAYLAB_CXX_COMPILER, "-nostdinc", "-MD", "-MF",
                                      (root / "file.d").string(), "-c", (submission / file).string(), "-o",
                                      (root / "file.o").string()};
        return runProgram(argv, root / "output.txt", root);
    }
    bool objectExists() const { return fs::exists(root / "file.o"); }
    std::string object() const { return readFile(root / "file.o"); }
};

// The modes this system has: the dependency file's check always, bubblewrap when it works here.
std::vector<bool> modes() {
    if (raylab::grader::bubblewrapMissing().empty()) return {false, true};
    MESSAGE("bubblewrap cannot run here: only the dependency file's check is tested");
    return {false};
}

const std::string kSecret = "the reference answer, which no submission may read";

} // namespace

TEST_SUITE("build guard") {

TEST_CASE("a file that includes only its own folder's files compiles") {
    for (bool confined : modes()) {
        CAPTURE(confined);
        const Folders f;
        const ProgramRun run = f.compile("honest.cpp", "#include \"own.h\"\nint f() { return own(); }\n", confined);
        CHECK_MESSAGE(run.status == 0, run.output);
        CHECK(f.objectExists());
        CHECK(readFile(f.root / "file.d").find("own.h") != std::string::npos); // the dependency file is where the build expects it
        CHECK(std::distance(fs::directory_iterator(f.root), fs::directory_iterator()) == 5); // no private folder left
    }
}

TEST_CASE("including a file outside the allowed folders is refused, through .., an absolute path or a symlink") {
    for (bool confined : modes()) {
        const Folders f;
        fs::create_symlink(f.secret / "answer.h", f.submission / "link.h");
        for (const std::string& include :
             {std::string("../solutions/answer.h"), (f.secret / "answer.h").string(), std::string("link.h")}) {
            CAPTURE(confined);
            CAPTURE(include);
            const ProgramRun run = f.compile("sneaky.cpp", "#include \"" + include + "\"\nint f() { return answer(); }\n", confined);
            CHECK(run.status == 1);
            CHECK_FALSE(f.objectExists());
            if (confined) { // the file is not there for the compiler
                CHECK_MESSAGE(run.output.find("No such file") != std::string::npos, run.output);
            } else { // the dependency file names it
                CHECK_MESSAGE(run.output.find("raylab-build-guard: outside: ") != std::string::npos, run.output);
                CHECK(run.output.find(fs::canonical(f.secret / "answer.h").string()) != std::string::npos);
            }
        }
    }
}

TEST_CASE("a system header under /usr/lib is not outside (Debian 13's asm/*.h, linked there)") {
    // Debian 13's /usr/include/<triplet>/asm/*.h are links to /usr/lib/linux/uapi/, and GCC 14's
    // dependency file names the link's target: a header of the system, as if included by that name.
    fs::path header; // GCC's own stddef.h: no include of its own, so it compiles under -nostdinc
    std::error_code error;
    for (auto it = fs::recursive_directory_iterator("/usr/lib/gcc", error); !error && it != fs::recursive_directory_iterator();
         it.increment(error))
        if (it->path().filename() == "stddef.h") header = it->path();
    if (header.empty()) {
        MESSAGE("skipped: no stddef.h under /usr/lib/gcc");
        return;
    }
    for (bool confined : modes()) {
        CAPTURE(confined);
        const Folders f;
        const ProgramRun run =
            f.compile("system.cpp", "#include \"" + header.string() + "\"\nsize_t f() { return sizeof(int); }\n", confined);
        CHECK_MESSAGE(run.status == 0, run.output);
        CHECK(f.objectExists());
    }
}

TEST_CASE("the assembler's .incbin of a file outside: under bubblewrap it does not compile; the dependency file does not "
          "see it") {
    for (bool confined : modes()) {
        CAPTURE(confined);
        const Folders f;
        std::ofstream(f.secret / "answer.txt") << kSecret;
        const ProgramRun run = f.compile(
            "incbin.cpp", "asm(\".section .rodata\\n.incbin \\\"" + (f.secret / "answer.txt").string() + "\\\"\\n.text\");\n", confined);
        CHECK(run.output.find(kSecret) == std::string::npos);
        if (confined) {
            CHECK(run.status == 1);
            CHECK_MESSAGE(run.output.find("file not found") != std::string::npos, run.output);
            CHECK_FALSE(f.objectExists());
        } else { // why the compiler must be confined: the second wall alone lets it through
            CHECK(run.status == 0);
            CHECK(f.object().find(kSecret) != std::string::npos);
        }
    }
}

TEST_CASE("the fallback (root, RAYLAB_SANDBOX=fallback): the compiler runs as an unprivileged user, its objects are root's") {
    if (geteuid() != 0) {
        MESSAGE("SKIPPED: only root can run the fallback; not root here");
        return;
    }
    const Folders f;
    const ProgramRun honest = f.compileIn("fallback", "honest.cpp", "#include \"own.h\"\nint f() { return own(); }\n");
    CHECK_MESSAGE(honest.status == 0, honest.output);
    struct stat object {};
    REQUIRE(stat((f.root / "file.o").c_str(), &object) == 0);
    CHECK(object.st_uid == 0); // given back: nothing the user left running can rewrite it
    CHECK(std::distance(fs::directory_iterator(f.root), fs::directory_iterator()) == 5); // no private folder left
    // A file in a folder only root can read: the compiler cannot .incbin it (as root it could).
    fs::remove(f.root / "file.o");
    std::ofstream(f.secret / "answer.txt") << kSecret;
    fs::permissions(f.secret, fs::perms::owner_all);
    const std::string incbin = "asm(\".section .rodata\\n.incbin \\\"" + (f.secret / "answer.txt").string() + "\\\"\\n.text\");\n";
    const ProgramRun confined = f.compileIn("fallback", "incbin.cpp", incbin);
    CHECK(confined.status != 0);
    CHECK(confined.output.find(kSecret) == std::string::npos);
    CHECK_FALSE(f.objectExists());
    const ProgramRun open = f.compileIn("none", "incbin.cpp", incbin);
    CHECK(open.status == 0);
    CHECK(f.object().find(kSecret) != std::string::npos);
}

TEST_CASE("the fallback compiles a tree under a folder of mode 0700 (as /root): on copies, its words and dependency file "
          "naming the original files; nothing else of the tree is there for it") {
    if (geteuid() != 0) {
        MESSAGE("SKIPPED: only root can run the fallback; not root here");
        return;
    }
    const Folders f;
    // home/ is closed to every other user, as /root is; what the tree holds inside is world-readable.
    const fs::path home = f.root / "home", tree = home / "tree", build = home / "build";
    for (const fs::path& folder : {tree / "submission", tree / "include", tree / "solutions", build})
        fs::create_directories(folder);
    fs::permissions(home, fs::perms::owner_all);
    std::ofstream(tree / "include" / "kit.h") << "inline int kit() { return 2; }\n";
    std::ofstream(tree / "submission" / "own.h") << "inline int own() { return 1; }\n";
    std::ofstream(tree / "solutions" / "answer.txt") << kSecret;
    const auto compile = [&](const std::string& body) {
        std::ofstream(tree / "submission" / "file.cpp") << body;
        // As CMake's Ninja writes it: the source relative to the build folder, the outputs in it.
        return runProgram({"/usr/bin/env", "RAYLAB_SANDBOX=fallback", (fs::path(RAYLAB_GRADING_BIN) / "raylab-build-guard").string(),
                           "--allow", (tree / "submission").string(), "--", RAYLAB_CXX_COMPILER, "-nostdinc",
                           "-I" + (tree / "include").string(), "-MD", "-MT", "file.o", "-MF", "file.d", "-c",
                           "../tree/submission/file.cpp", "-o", "file.o"},
                          f.root / "output.txt", build);
    };
    const ProgramRun honest = compile("#include \"own.h\"\n#include <kit.h>\nint f() { return own() + kit(); }\n");
    REQUIRE_MESSAGE(honest.status == 0, honest.output);
    struct stat object {};
    REQUIRE(stat((build / "file.o").c_str(), &object) == 0);
    CHECK(object.st_uid == 0);
    const std::string dependencies = readFile(build / "file.d");
    CHECK_MESSAGE(dependencies.find((tree / "include" / "kit.h").string()) != std::string::npos, dependencies);
    CHECK_MESSAGE(dependencies.find((tree / "submission" / "own.h").string()) != std::string::npos, dependencies);
    CHECK(dependencies.find("raylab-compile") == std::string::npos);
    CHECK(std::distance(fs::directory_iterator(build), fs::directory_iterator()) == 2); // file.o, file.d: nothing else

    const ProgramRun wrong = compile("int f() { return missing_name; }\n");
    CHECK(wrong.status != 0);
    CHECK_MESSAGE(wrong.output.find((tree / "submission" / "file.cpp").string() + ":1") != std::string::npos, wrong.output);
    CHECK(wrong.output.find("raylab-compile") == std::string::npos);

    // A world-readable file of the tree that was not allowed: not copied, so not there for the compiler.
    fs::remove(build / "file.o");
    const ProgramRun stealing =
        compile("asm(\".section .rodata\\n.incbin \\\"" + (tree / "solutions" / "answer.txt").string() + "\\\"\\n.text\");\n");
    CHECK(stealing.status != 0);
    CHECK(stealing.output.find(kSecret) == std::string::npos);
    CHECK_FALSE(fs::exists(build / "file.o"));
}

TEST_CASE("the fallback with Landlock: the compiler reads the system's headers, and .incbin of a world-readable file fails") {
    if (geteuid() != 0 || raylab::grader::detail::landlockAbi() == 0) {
        MESSAGE("SKIPPED: needs root (the fallback) and a kernel with Landlock");
        return;
    }
    const Folders f;
    // A classmate's file in a world-readable class folder: the unprivileged user could read it.
    std::ofstream(f.secret / "answer.txt") << kSecret;
    fs::permissions(f.root, fs::perms(0755));
    fs::permissions(f.secret, fs::perms(0755));
    fs::permissions(f.secret / "answer.txt", fs::perms(0644));
    const auto compile = [&](const std::string& body) {
        std::ofstream(f.submission / "file.cpp") << body;
        return runProgram({"/usr/bin/env", "RAYLAB_SANDBOX=fallback", (fs::path(RAYLAB_GRADING_BIN) / "raylab-build-guard").string(),
                           "--allow", f.submission.string(), "--allow", "/usr", "--", RAYLAB_CXX_COMPILER, "-MD", "-MF",
                           (f.root / "file.d").string(), "-c", (f.submission / "file.cpp").string(), "-o", (f.root / "file.o").string()},
                          f.root / "output.txt", f.root);
    };
    const ProgramRun honest = compile("#include <vector>\nint f() { return int(std::vector<int>(3).size()); }\n");
    CHECK_MESSAGE(honest.status == 0, honest.output);
    fs::remove(f.root / "file.o");
    const ProgramRun stealing =
        compile("asm(\".section .rodata\\n.incbin \\\"" + (f.secret / "answer.txt").string() + "\\\"\\n.text\");\n");
    CHECK(stealing.status != 0);
    CHECK(stealing.output.find(kSecret) == std::string::npos);
    CHECK_FALSE(f.objectExists());
}

TEST_CASE("an object file past kCompilerFileBytes stops the assembler, under every sandbox; nothing of it is left") {
    std::vector<std::string> sandboxes{"none"};
    if (raylab::grader::bubblewrapMissing().empty()) sandboxes.push_back("bubblewrap");
    if (geteuid() == 0) sandboxes.push_back("fallback");
    else MESSAGE("the fallback needs root: not tested here");
    for (const std::string& sandbox : sandboxes) {
        CAPTURE(sandbox);
        const Folders f;
        // 100 MB of data from a line of source: the object would be that large.
        const ProgramRun run = f.compileIn(sandbox, "big.cpp", "asm(\".section .rodata\\n.fill 100000000, 1, 1\\n.text\");\n");
        CHECK(run.status != 0);
        CHECK_MESSAGE(run.output.find("File size limit exceeded") != std::string::npos, run.output); // the grader's cue
        CHECK_FALSE(f.objectExists());
        for (const auto& entry : fs::directory_iterator(f.root)) // no private folder left
            CHECK(entry.path().filename().string().rfind(".raylab-guard-", 0) == std::string::npos);
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
    CHECK_MESSAGE(run.output.find("raylab-build-guard: time: sleep") != std::string::npos, run.output);
    CHECK(seconds < 30.); // far below the sleep's 60 s: it was killed, not waited for
}

TEST_CASE("the build's deadline: past it a file is not compiled, before it it stops a compile that would outlast it") {
    const Folders f;
    const fs::path output = f.root / "output.txt";
    const auto guard = [&](long long deadlineFromNow) {
        fs::remove(output);
        const std::string deadline = std::to_string(static_cast<long long>(std::time(nullptr)) + deadlineFromNow);
        // A stand-in "compiler" that never ends: sleep, under the file's own limit of 300 s.
        const raylab::grader::ProcessResult r = raylab::grader::runProcess({(fs::path(RAYLAB_GRADING_BIN) / "raylab-build-guard").string(), "--", "sleep", "60"},
                                           {{}, output, 0., {"RAYLAB_BUILD_DEADLINE=" + deadline}});
        CHECK(r.exitCode == 1);
        return readFile(output);
    };
    const std::string spent = guard(-1);
    CHECK_MESSAGE(spent.find("raylab-build-guard: build-time: sleep") != std::string::npos, spent);
    const std::string stopped = guard(1);
    CHECK_MESSAGE(stopped.find("raylab-build-guard: build-time: sleep") != std::string::npos, stopped);
}

} // TEST_SUITE

#endif
