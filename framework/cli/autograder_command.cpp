// raylab autograder: grading where the students hand in (docs/instructors.md, section 3).
//   gradescope OUT.zip  the autograder zip: setup.sh, run_autograder and the students' tree (raylab/)
//   github OUT_DIR      the students' tree with GitHub Classroom's workflow, one step per item
//   run                 what run_autograder calls, inside Gradescope's container
#include "build_info.h"
#include "commands.h"

#include "grader/course/autograder.h"
#include "grader/sandbox/process.h"
#include "grader/course/grade_reports.h"
#include "src/atomic_file.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <random>
#include <string>

namespace raylab::cli {

namespace {

namespace fs = std::filesystem;
using namespace raylab::grader;

int writeGradescopeZip(const fs::path& zip) {
    std::vector<ZipEntry> entries{{"setup.sh", {}, gradescopeSetupScript(), true},
                                  {"run_autograder", {}, gradescopeRunScript(), true}};
    const fs::path source = fs::canonical(build::kSourceDir);
    for (const fs::path& relative : studentTreeFiles(source)) {
        const fs::perms perms = fs::status(source / relative).permissions();
        entries.push_back({"raylab/" + relative.generic_string(), source / relative, {},
                           (perms & fs::perms::owner_exec) != fs::perms::none});
    }
    if (zip.has_parent_path()) fs::create_directories(zip.parent_path());
    writeZip(zip, entries);
    std::printf("raylab autograder gradescope: %s (setup.sh, run_autograder and the students' tree, %zu files)\n"
                "  upload it as the assignment's autograder (Ubuntu 24.04 image); see docs/instructors.md\n",
                zip.string().c_str(), entries.size() - 2);
    return 0;
}

int writeClassroomTree(const fs::path& out, const Context& context) {
    const LabCatalog catalog = loadLabCatalog(labsFolder(), context.scenes);
    const int files = writeStudentTree(build::kSourceDir, out);
    const fs::path workflow = out / ".github" / "workflows" / "classroom.yml";
    fs::create_directories(workflow.parent_path());
    writeFileAtomically(workflow, classroomWorkflow(catalog));
    std::printf("raylab autograder github: %d files and %s (%zu graded steps) -> %s\n"
                "  push it as the assignment's template repository; see docs/instructors.md\n",
                files, workflow.lexically_relative(out).generic_string().c_str(), classroomSteps(catalog).size(),
                out.string().c_str());
    return 0;
}

// Inside Gradescope's container: the submission's labs into the tree, `raylab grade --labs` on them
// (its own process: whatever happens to it, results.json is written), results.json into results/.
int runGradescope(const Context& context) {
    const fs::path root = autograderRoot(), results = root / "results";
    const fs::path tree = build::kSourceDir, submitted = tree / "submission";
    fs::create_directories(results);
    std::error_code error;
    fs::remove(results / "results.json", error);
    std::string why;
    try {
        const LabCatalog catalog = loadLabCatalog(labsFolder(), context.scenes);
        copySubmittedLabs(root / "submission", catalog, submitted);
        std::fflush(stdout); // what we printed comes before what it prints
        const int status = runProcess({(fs::path(build::kBinaryDir) / "raylab").string(), "grade", "--labs",
                                       submitted.string(), "--build-dir", (tree / "build").string(), "--report",
                                       results.string()})
                               .exitCode;
        if (fs::exists(results / "results.json", error)) return 0;
        why = "the grader stopped (exit status " + std::to_string(status) + ") before it wrote the results";
    } catch (const std::exception& e) {
        why = e.what();
    }
    std::printf("raylab autograder run: %s\n", why.c_str());
    std::random_device random;
    const fs::path scratch = fs::temp_directory_path() / ("raylab-autograder-" + std::to_string(random()));
    GradeResult nothing = gradeBuildFailure(loadGradeSetup(referencesFolder(), labsFolder(), context.scenes, scratch), why);
    fs::remove_all(scratch, error);
    writeGradescopeJson(nothing, results / "results.json");
    return 0;
}

} // namespace

void addAutograderCommand(CLI::App& app, Context& context) {
    CLI::App* autograder = app.add_subcommand("autograder", "instructors: grade on Gradescope or GitHub Classroom");
    autograder->require_subcommand(1);

    auto zip = std::make_shared<std::string>();
    CLI::App* gradescope =
        autograder->add_subcommand("gradescope", "write Gradescope's autograder zip (setup.sh, run_autograder, the tree)");
    gradescope->add_option("OUT.zip", *zip, "the zip to write")->required();
    gradescope->callback([&context, zip] { context.exitStatus = writeGradescopeZip(*zip); });

    auto out = std::make_shared<std::string>();
    CLI::App* github = autograder->add_subcommand(
        "github", "write the students' tree with GitHub Classroom's workflow (.github/workflows/classroom.yml)");
    github->add_option("OUT_DIR", *out, "the folder to create")->required();
    github->callback([&context, out] { context.exitStatus = writeClassroomTree(*out, context); });

    CLI::App* run = autograder->add_subcommand(
        "run", "inside Gradescope (run_autograder): grade $RAYLAB_AUTOGRADER_ROOT/submission (default /autograder)");
    run->callback([&context] { context.exitStatus = runGradescope(context); });
}

} // namespace raylab::cli
