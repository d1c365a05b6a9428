// The commands as a user mistypes them and as a full disk answers them: a clear error that names
// what is wrong, a non-zero exit status, never a hang, an abort or an old file destroyed.
#include "support/scene_files.h"
#include "support/files.h"
#include "grading_support.h"

#include <fstream>
#include <string>
#include <vector>
#if defined(__unix__) || defined(__APPLE__)
#include "program_process.h"
#include <sys/stat.h>
#define RAYLAB_COMMAND_ERROR_TESTS 1
#endif

using namespace raylab::test;

#ifdef RAYLAB_COMMAND_ERROR_TESTS

namespace {

struct Finished {
    int status = -1;
    std::string output;
};

// Runs a program of the build (raylab, raylab-reference) to its end; a minute at most.
Finished run(const std::string& program, const std::vector<std::string>& args, long fileSizeLimit = 0) {
    const fs::path output = fs::temp_directory_path() / ("raylab-command-errors-" + std::to_string(getpid()) + ".txt");
    const ProgramProcess process = startProgram(binDir() / program, args, output, fileSizeLimit);
    Finished done;
    done.status = process.finishWithin(60.);
    done.output = process.text();
    fs::remove(output);
    return done;
}

using raylab::test::freshFolder;
using raylab::test::readFile;

bool has(const Finished& f, const std::string& text) { return f.output.find(text) != std::string::npos; }

const std::string kGradientScene = raylab::test::figureSceneFile("lab1_gradient").string();

} // namespace

TEST_SUITE("command errors") {

TEST_CASE("an unknown command is named, with the list of commands") {
    const Finished f = run("raylab", {"frobnicate"});
    CHECK(f.status != 0);
    CHECK_MESSAGE(has(f, "unknown command 'frobnicate'; commands are: "), f.output);
    CHECK_MESSAGE(has(f, "grade-class"), f.output);
    CHECK_MESSAGE(has(f, "figures"), f.output);
}

TEST_CASE("--threads: 0 (one per core) to 1024; more is refused with the limit, never an abort") {
    const Finished tooMany = run("raylab", {"render", kGradientScene, "--threads", "100000"});
    CHECK(tooMany.status != 0);
    CHECK(tooMany.status < 128); // not killed by a signal (SIGABRT was 134)
    CHECK_MESSAGE(has(tooMany, "100000 is more threads than raylab starts: at most 1024"), tooMany.output);
    const Finished huge = run("raylab", {"render", kGradientScene, "--threads", "99999999999999999999999"});
    CHECK_MESSAGE(has(huge, "at most 1024"), huge.output);
    const Finished negative = run("raylab", {"grade", "--threads", "-2"});
    CHECK(negative.status != 0);
    CHECK_MESSAGE(has(negative, "'-2' is not a number of threads"), negative.output);
}

TEST_CASE("--timeout: a positive number of seconds; 0, -5, nan and inf are refused") {
    for (const char* bad : {"0", "-5", "nan", "inf", "soon"}) {
        CAPTURE(bad);
        const Finished f = run("raylab", {"grade", "--timeout", bad});
        CHECK(f.status != 0);
        CHECK_MESSAGE(has(f, std::string("'") + bad + "' is not a time limit"), f.output);
    }
}

TEST_CASE("grade --images reads regular files only: a pipe or a device is refused at once") {
    // The course's first figure a picture, its last a pipe, the one before a link to a device.
    std::vector<std::string> ids;
    for (const LabDescription& lab : loadLabCatalog(sourceDir() / "labs").labs)
        for (const LabFigure& figure : lab.figures) ids.push_back(figure.id);
    REQUIRE(ids.size() >= 3);
    const std::string& good = ids.front();
    const std::string& pipe = ids.back();
    const std::string& device = ids[ids.size() - 2];
    const fs::path dir = freshFolder("raylab-images-special");
    REQUIRE(mkfifo((dir / (pipe + ".png")).c_str(), 0600) == 0);
    fs::create_symlink("/dev/zero", dir / (device + ".png"));
    fs::copy_file(referencePicture(good), dir / (good + ".png"));
    const Finished f = run("raylab", {"grade", "--images", dir.string(), "--report", (dir / "report").string()});
    REQUIRE_MESSAGE(f.status != -1, "still running after a minute: it blocked on the pipe");
    CHECK(f.status == 1);
    CHECK_MESSAGE(has(f, "FAIL  " + pipe), f.output);
    CHECK_MESSAGE(has(f, (dir / (pipe + ".png")).string() + " is not a regular file"), f.output);
    CHECK_MESSAGE(has(f, (dir / (device + ".png")).string() + " is not a regular file"), f.output);
    CHECK_MESSAGE(has(f, "PASS  " + good), f.output);
}

#ifdef __linux__
TEST_CASE("render --out /dev/full: the write error names the file and the reason, the status is 1") {
    const Finished f = run("raylab-reference", {"render", kGradientScene, "--out", "/dev/full"});
    CHECK(f.status == 1);
    CHECK_MESSAGE(has(f, "cannot write /dev/full: No space left on device"), f.output);
}
#endif

TEST_CASE("figures into a folder that cannot exist: each figure failed with the reason, the status is 1") {
    const fs::path dir = freshFolder("raylab-figures-unwritable");
    std::ofstream(dir / "a_regular_file") << "not a folder";
    const fs::path out = dir / "a_regular_file" / "figures";
    const Finished f = run("raylab-reference", {"figures", "--only", "lab1_gradient", "--out", out.string()});
    CHECK(f.status == 1);
    CHECK_MESSAGE(has(f, "lab1_gradient            FAILED  cannot write " + (out / "lab1_gradient.png").string()), f.output);
    CHECK_MESSAGE(has(f, "1 figure: 0 rendered, 0 waiting for a lab not done yet, 1 failed"), f.output);
}

TEST_CASE("figures --handouts writes the handouts' pictures from the reference build only") {
    const fs::path picture = sourceDir() / "labs/lab1_first_image/figures/lab1_gradient.png";
    const auto before = fs::last_write_time(picture);
    const Finished student = run("raylab", {"figures", "--handouts", "--only", "lab1_gradient"});
    CHECK(student.status != 0);
    CHECK(student.status < 128);
    CHECK_MESSAGE(has(student, "--handouts writes the handouts' pictures, which are the reference's"), student.output);
    const Finished both = run("raylab-reference", {"figures", "--handouts", "--out", "somewhere"});
    CHECK(both.status != 0);
    CHECK_MESSAGE(has(both, "--out excludes --handouts"), both.output);
    CHECK(fs::last_write_time(picture) == before); // neither wrote anything
}

TEST_CASE("a write cut short (a nearly full disk) fails with the file named and leaves the old file whole") {
    const fs::path dir = freshFolder("raylab-write-cut-short");
    const fs::path png = dir / "gradient.png";
    std::ofstream(png) << "the old picture";
    // 600 x 400 gradient: its PNG is far more than 4 KiB.
    const Finished f = run("raylab-reference", {"render", kGradientScene, "--out", png.string()}, 4096);
    CHECK(f.status == 1);
    CHECK_MESSAGE(has(f, "cannot write " + png.string() + ": File too large"), f.output);
    CHECK(readFile(png) == "the old picture");
    std::vector<std::string> left;
    for (const auto& entry : fs::directory_iterator(dir)) left.push_back(entry.path().filename().string());
    CHECK(left == std::vector<std::string>{"gradient.png"}); // no temporary file left behind

    const Finished whole = run("raylab-reference", {"render", kGradientScene, "--out", png.string()});
    CHECK_MESSAGE(whole.status == 0, whole.output);
    CHECK(readFile(png).rfind("\x89PNG", 0) == 0);
}

TEST_CASE("report into an unwritable place: an error naming the file, a non-zero status") {
    const fs::path dir = freshFolder("raylab-report-unwritable");
    std::ofstream(dir / "a_regular_file") << "not a folder";
    const Finished f = run("raylab-reference", {"report", "--out", (dir / "a_regular_file" / "kit").string()});
    CHECK(f.status != 0);
    CHECK_MESSAGE(has(f, "raylab: error: "), f.output);
    CHECK_MESSAGE(has(f, (dir / "a_regular_file" / "kit").string()), f.output);
    CHECK_MESSAGE(has(f, "Not a directory"), f.output);
}

} // TEST_SUITE

#endif
