// A submission's compiler runs under bubblewrap, or the fallback with Landlock (raylab-build-guard):
// a lab file whose assembler `.incbin`s the reference solution, then throws those bytes as an
// exception message (the message would reach results.json), does not build. That lab gets 0 and no line of the solution appears in
// anything `raylab grade` writes. The submission is written here, not as a patch of bad_submissions/:
// those are built with the tests, and this one must not build.
#include "grader/sandbox/landlock.h"
#include "grading_support.h"
#include "support/files.h"
#include "support/run_program.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace raylab::test;

namespace {

const fs::path kSolution = sourceDir() / "solutions" / "lab3_sphere" / "sphere_geometry.cpp";

// The solution of lab 3 with a computeNormal that throws the bytes its assembler read from `stolen`.
std::string stealingLab3(const fs::path& stolen) {
    std::string code = readFile(kSolution);
    // The honest definition, found by its signature (its body is lab 3's answer: not written here,
    // as this file goes to students).
    const std::size_t at = code.find("glm::vec3 SphereGeometry::computeNormal(");
    const std::size_t end = code.find("}\n", at);
    REQUIRE_MESSAGE(end != std::string::npos, "solutions/lab3_sphere/sphere_geometry.cpp changed: update this test");
    code.replace(at, end + 1 - at,
                 "extern \"C\" const char raylab_stolen[];\n"
                 "asm(\".section .rodata\\n.global raylab_stolen\\nraylab_stolen:\\n.incbin \\\"" + stolen.string() +
                     "\\\"\\n.byte 0\\n.text\");\n"
                     "glm::vec3 SphereGeometry::computeNormal(const glm::vec3&) const { throw std::runtime_error(raylab_stolen); }");
    return "#include <stdexcept>\n" + code;
}

// Whether `text` holds one of the solution's lines of 30 characters or more.
bool holdsSolution(const std::string& text) {
    std::istringstream lines(readFile(kSolution));
    for (std::string line; std::getline(lines, line);)
        if (line.size() >= 30 && text.find(line) != std::string::npos) return true;
    return false;
}

} // namespace

TEST_SUITE("confined build") {

TEST_CASE("a lab file that .incbin's the solution does not build, under bubblewrap and the fallback: 0 for that lab, no byte of it anywhere") {
    std::vector<std::string> sandboxes;
    if (bubblewrapMissing().empty()) sandboxes.push_back("bubblewrap");
    else MESSAGE("bubblewrap cannot run here (" << bubblewrapMissing() << "): not tested with it");
    // The fallback holds only with Landlock: without it the compiler reads every world-readable file.
    if (geteuid() == 0 && raylab::grader::detail::landlockAbi() > 0) sandboxes.push_back("fallback");
    else MESSAGE("not root, or no Landlock here: not tested with the fallback");
    for (const std::string& sandbox : sandboxes) {
        CAPTURE(sandbox);
        const fs::path root = freshFolder("raylab-confined-build");
        fs::create_directories(root / "submission" / "lab3_sphere");
        std::ofstream(root / "submission" / "lab3_sphere" / "sphere_geometry.cpp") << stealingLab3(kSolution);
        // out/build: the depth of the other grading builds, whose objects the compiler cache shares (tests/grading/CMakeLists.txt).
        const ProgramRun run = runProgram({"/usr/bin/env", "RAYLAB_SANDBOX=" + sandbox, (binDir() / "raylab").string(), "grade",
                                           "--labs", (root / "submission").string(), "--build-dir",
                                           (root / "out" / "build").string(), "--report", (root / "report").string(), "--lab", "3"},
                                          root / "output.txt", root);
        CHECK_MESSAGE(run.output.find("file not found") != std::string::npos, run.output); // the assembler's, in the sandbox
        std::ifstream in(root / "report" / "results.json");
        const nlohmann::json results = nlohmann::json::parse(in);
        CHECK(results["score"].get<double>() == 0.);
        CHECK_FALSE(holdsSolution(run.output));
        for (const auto& entry : fs::recursive_directory_iterator(root / "report")) {
            CAPTURE(entry.path());
            if (entry.is_regular_file()) CHECK_FALSE(holdsSolution(readFile(entry.path())));
        }
        std::error_code ignored;
        fs::remove_all(root, ignored);
    }
}

} // TEST_SUITE
