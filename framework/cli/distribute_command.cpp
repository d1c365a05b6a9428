// raylab distribute: writes the tree students receive: everything but the reference solutions and
// what would give them away (the mistakes in each lab's grading folder, the valid variants and bad
// submissions of tests/ are patches against the solutions, which show their lines; the studies and tests that hold a lab's answer are
// built only where solutions/ is). It builds, runs and self-grades on its own: the
// labs' descriptions (labs/<lab>/lab.toml: items and points) and the grader's references (each
// lab's framework/grader/labs/<lab>/references/) go with it. tests/grading/distribute_ships_no_solution.cpp
// checks what it writes.
#include "build_info.h"
#include "commands.h"

#include "grader/lab_catalog.h"
#include "src/messages.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace raylab::cli {

namespace {

namespace fs = std::filesystem;

grader::LabCatalog courseCatalog(const fs::path& source) {
    return grader::loadLabCatalog(source / "labs");
}

// Paths relative to the source tree that are not handed out.
const std::set<std::string> kWithheld{"solutions", "tests/variants", "tests/grading/bad_submissions",
                                      ".git", "out", "compile_commands.json", ".cache",
                                      // raylab bench's yardstick writes the solutions' formulas out
                                      "framework/study/yardstick.cpp",
                                      // lab 3's intersection, written out for raylab numerics and study
                                      // intersection (built only where solutions/ is), and what needs it
                                      "framework/study/sphere_formulas.h", "framework/study/numerics_study.h",
                                      "framework/study/intersection_study.cpp", "framework/study/image_study.cpp",
                                      "framework/study/accumulation_study.cpp", "framework/cli/numerics_command.cpp",
                                      "tests/numerics",
                                      // the reference shading with point lights: a lab on shadows' answer
                                      "framework/study/lambert_shading.cpp",
                                      // a complete lab 3 sphere that counts its calls, and its test
                                      "tests/study/counting_sphere.cpp", "tests/study/counting_sphere.h",
                                      "tests/study/test_render_work.cpp",
                                      // the toy lab's answer, a lab's solution in the toy-lab test's tree
                                      "tests/labs/toy/solution"};

// The labs' folders that are not handed out: every lab's in solutions/ (kWithheld), its mistakes'
// patches (against the solutions, they show their lines), and in labs/ and the grading folders those
// of the labs the course's list (course.toml) leaves out: absent, not a zero.
std::set<std::string> labFoldersWithheld(const fs::path& source, const grader::LabCatalog& course) {
    std::set<std::string> folders;
    for (const auto& entry : fs::directory_iterator(source / "labs")) {
        const std::string id = entry.path().filename().string();
        folders.insert("framework/grader/labs/" + id + "/mistakes");
        if (!entry.is_directory() || course.labOfId(id) != nullptr) continue;
        folders.insert("labs/" + id);
        folders.insert("framework/grader/labs/" + id);
    }
    return folders;
}

bool withheld(const fs::path& relative, const std::set<std::string>& labFolders) {
    const std::string text = relative.generic_string();
    if (kWithheld.count(text) || labFolders.count(text)) return true;
    const std::string top = relative.begin()->string();
    return top.rfind("build", 0) == 0; // build folders
}

} // namespace

std::vector<fs::path> studentTreeFiles(const fs::path& source) {
    const fs::path sourceAbs = fs::canonical(source);
    const std::set<std::string> labFolders = labFoldersWithheld(sourceAbs, courseCatalog(sourceAbs));
    std::vector<fs::path> files;
    for (auto it = fs::recursive_directory_iterator(sourceAbs); it != fs::recursive_directory_iterator(); ++it) {
        const fs::path relative = it->path().lexically_relative(sourceAbs); // fs::relative would follow links
        if (withheld(relative, labFolders) || it->is_symlink()) {
            if (it->is_directory()) it.disable_recursion_pending();
            continue;
        }
        if (it->is_regular_file()) files.push_back(relative);
    }
    return files;
}

int writeStudentTree(const fs::path& source, const fs::path& out) {
    std::error_code error;
    if (fs::exists(out, error) && !fs::is_empty(out, error))
        throw std::invalid_argument(out.string() + " exists and is not empty; choose a new folder");
    const std::vector<fs::path> files = studentTreeFiles(source); // before `out` exists: never inside it
    const fs::path sourceAbs = fs::canonical(source);
    for (const fs::path& relative : files) {
        fs::create_directories((out / relative).parent_path());
        fs::copy_file(sourceAbs / relative, out / relative, fs::copy_options::overwrite_existing);
    }
    writeStudentsReadme(out, courseCatalog(sourceAbs));
    const bool hadReadme = std::find(files.begin(), files.end(), fs::path("README.md")) != files.end();
    return int(files.size()) + (hadReadme ? 1 : 2); // LISEZMOI.md, and README.md where there was none
}

namespace {

int distribute(const fs::path& source, const fs::path& out) {
    const int files = writeStudentTree(source, out);
    std::printf("%s\n", tr("distribute.written", {{"files", std::to_string(files)},
                                                   {"folder", out.string()},
                                                   {"build", kStudentsBuildCommand}})
                            .c_str());
    return 0;
}

} // namespace

void addDistributeCommand(CLI::App& app, Context& context) {
    auto out = std::make_shared<std::string>();
    CLI::App* command =
        app.add_subcommand("distribute", tr("cli.distribute"));
    command->add_option(tr("cli.type.DIR"), *out, tr("cli.new_folder"))->required();
    command->callback([&context, out] { context.exitStatus = distribute(build::kSourceDir, *out); });
}

} // namespace raylab::cli
