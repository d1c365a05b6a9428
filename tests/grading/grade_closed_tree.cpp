// The grader works wherever the tree is (issue 32): a copy of the students' tree in a folder of mode
// 0700 (as /root, or a home folder of 0700, is), mounted read-only where the test can make a mount
// namespace of its own (root), its build folder beside it in that folder. A submission is built and
// graded there under bubblewrap and under the fallback, whose unprivileged user cannot enter that
// folder: its compiler works on copies of what it may read (compile_stage.h), its agents run from
// copies (unprivileged.h). Both earn the same points, and a compile error names the student's file
// where it is, not a copy.
#include "grading_support.h"
#include "grader/course/submission.h"
#include "grader/sandbox/process.h"
#include "grader/sandbox/sandbox.h"
#include "support/files.h"
#include "support/run_program.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <unistd.h>
#ifdef __linux__
#include <sched.h>
#include <sys/mount.h>
#endif

using namespace raylab::test;

namespace {

// `tree` read-only for this process and what it starts, in a mount namespace of its own. False where
// that cannot be done (not root, or a container without the right).
bool mountReadOnly(const fs::path& tree) {
#ifdef __linux__
    if (geteuid() != 0 || unshare(CLONE_NEWNS) != 0) return false;
    return mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) == 0 &&
           mount(tree.c_str(), tree.c_str(), nullptr, MS_BIND | MS_REC, nullptr) == 0 &&
           mount(nullptr, tree.c_str(), nullptr, MS_BIND | MS_REMOUNT | MS_RDONLY, nullptr) == 0;
#else
    (void)tree;
    return false;
#endif
}

} // namespace

TEST_SUITE("closed tree") {

TEST_CASE("a read-only tree under a folder of mode 0700 grades the same under bubblewrap and the fallback") {
    std::vector<std::string> sandboxes;
    if (bubblewrapMissing().empty()) sandboxes.push_back("bubblewrap");
    else MESSAGE("bubblewrap cannot run here (" << bubblewrapMissing() << "): not tested with it");
    if (geteuid() == 0) sandboxes.push_back("fallback");
    else MESSAGE("not root: the fallback is not tested");
    if (sandboxes.empty()) return;

    const fs::path home = freshFolder("raylab-closed-tree") / "home", tree = home / "tree", build = home / "build";
    fs::create_directories(home);
    fs::permissions(home, fs::perms::owner_all); // closed to every other user
    const ProgramRun distributed =
        runProgram({(binDir() / "raylab").string(), "distribute", tree.string(), "--lang", "en"}, home / "distribute.txt");
    REQUIRE_MESSAGE(distributed.status == 0, distributed.output);
    const bool readOnly = mountReadOnly(tree);
    if (readOnly) CHECK_FALSE(std::ofstream(tree / "written").is_open()); // root too
    else MESSAGE("no mount namespace here: the tree is not read-only in this test");

    const raylab::grader::Toolchain tools{RAYLAB_CMAKE_COMMAND, RAYLAB_CMAKE_GENERATOR,
                                          raylab::grader::findProgram("ccache")};
    for (const std::string& sandbox : sandboxes) {
        CAPTURE(sandbox);
        setenv("RAYLAB_SANDBOX", sandbox.c_str(), 1); // the grader's and the build guard's (CMake starts it)
        // The course's solutions, one lab that another uses broken: a submission of its own for each
        // sandbox, so each compiles it.
        const fs::path submission = home / "submissions" / sandbox;
        copyCourseSolutions(submission);

        std::vector<fs::path> references;
        for (const LabDescription& lab : loadLabCatalog(tree / "labs").labs)
            references.push_back(tree / "framework/grader/labs" / lab.id / "references");
        GradeSetup setup = loadGradeSetup(references, tree / "labs", {}, home / ("scratch-" + sandbox));
        setup.limits.wallSeconds = 60.;
        setup.threads = 2;
        const LabDescription lab = usedLab(setup.labs);
        const fs::path source = submission / lab.id / lab.files().front();
        const std::string code = readFile(source);
        std::ofstream(source) << "this line is not C++\n" << code;
        CHECK(sandboxKind(setup.limits).rfind(sandbox == "fallback" ? "unprivileged user" : "bubblewrap", 0) == 0);
        const raylab::grader::SubmissionBuild b =
            raylab::grader::buildSubmission(tools, tree, submission, build, setup.labs);
        const std::vector<int> broken = labAndItsUsers(setup.labs, lab.number);
        CHECK_MESSAGE(b.brokenLabs == broken, b.compilerMessage);
        CHECK_MESSAGE(b.compilerMessage.find(source.string() + ":1") != std::string::npos, b.compilerMessage);
        CHECK(b.compilerMessage.find("raylab-compile") == std::string::npos);
        const GradeResult result = gradeCode(setup, b.agents, b.isolated, b.brokenLabs, b.compilerMessage);
        fs::remove_all(setup.scratch);
        // The broken lab and the labs that use it score 0 (no solutions/ to stand in), every other lab all its points.
        REQUIRE(!result.labs.empty());
        for (const LabOutcome& outcome : result.labs) {
            CAPTURE(outcome.lab);
            const bool isBroken = std::find(broken.begin(), broken.end(), outcome.lab) != broken.end();
            CHECK_MESSAGE(outcome.points == (isBroken ? 0. : outcome.maxPoints), failures(result));
        }
    }
    unsetenv("RAYLAB_SANDBOX");
    std::error_code ignored;
#ifdef __linux__
    if (readOnly) umount2(tree.c_str(), MNT_DETACH); // so that it can be removed
#endif
    fs::remove_all(home.parent_path(), ignored);
}

} // TEST_SUITE
