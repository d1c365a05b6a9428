// raylab autograder: grading where the students hand in (docs/instructors.md, section 3).
//   gradescope FILE.zip the autograder zip: setup.sh, run_autograder and the students' tree (raylab/)
//   github DIR          the students' tree with GitHub Classroom's workflow, one step per item
//   run                 what run_autograder calls, inside Gradescope's container
#include "build_info.h"
#include "commands.h"

#include "grader/course/autograder.h"
#include "grader/sandbox/process.h"
#include "grader/sandbox/sandbox.h"
#include "grader/course/grade_reports.h"
#include "src/atomic_file.h"
#include "src/messages.h"
#include "third_party_sources.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <filesystem>
#include <memory>
#include <random>
#include <stdexcept>
#include <stdlib.h> // mkdtemp
#include <string>

namespace raylab::cli {

namespace {

namespace fs = std::filesystem;
using namespace raylab::grader;

#ifndef RAYLAB_GRADING_ONLY // the instructors' side: a grading-only build has neither libzip nor distribute
#ifndef RAYLAB_NO_GRADESCOPE_ZIP // left out where libzip is missing (RAYLAB_GRADESCOPE_ZIP)
// The header-only libraries this program was built with, as third_party/<name>/ of the tree it writes
// (include/ and the licence): Gradescope's Ubuntu 22.04 lacks toml++, and the zip's setup.sh installs
// nothing but a compiler, CMake, make and zlib (cmake/RaylabDependencies.cmake takes them from there).
std::vector<ZipEntry> thirdPartyEntries() {
    std::vector<ZipEntry> entries;
    for (const build::ThirdPartySource& library : build::kThirdPartySources) {
        const std::string folder = std::string("raylab/third_party/") + library.name + "/";
        const fs::path licence = library.licence;
        if (licence.empty() || !fs::is_regular_file(licence))
            throw std::runtime_error(tr("autograder.no_licence", {{"library", library.name}, {"folder", library.includeDir}}));
        entries.push_back({folder + licence.filename().string(), licence, {}, false});
        const fs::path include = library.includeDir;
        std::string list = library.entries;
        for (std::size_t start = 0; start <= list.size();) {
            const std::size_t end = std::min(list.find(';', start), list.size());
            const fs::path entry = list.substr(start, end - start);
            start = end + 1;
            const auto add = [&](const fs::path& file) {
                entries.push_back({folder + "include/" + file.lexically_relative(include).generic_string(), file, {}, false});
            };
            if (fs::is_regular_file(include / entry)) add(include / entry);
            else if (fs::is_directory(include / entry)) {
                for (const auto& file : fs::recursive_directory_iterator(include / entry))
                    if (file.is_regular_file()) add(file.path());
            } else {
                throw std::runtime_error(tr("autograder.no_header", {{"library", library.name}, {"path", (include / entry).string()}}));
            }
        }
    }
    return entries;
}

// The reference labs (solutions/<lab folder>/*.cpp): the zip's setup.sh compiles them once and deletes
// them, so that each lab of a submission is graded with the others' reference.
std::vector<ZipEntry> referenceLabEntries(const fs::path& source, const LabCatalog& catalog) {
    std::vector<ZipEntry> entries;
    for (const LabDescription& lab : catalog.labs) {
        const fs::path folder = source / "solutions" / lab.id;
        std::error_code error;
        for (const auto& file : fs::directory_iterator(folder, error))
            if (file.is_regular_file() && file.path().extension() == ".cpp")
                entries.push_back({"raylab/solutions/" + lab.id + "/" + file.path().filename().string(), file.path(), {}, false});
        if (error || entries.empty()) throw std::runtime_error(tr("autograder.no_reference", {{"folder", folder.string()}}));
    }
    return entries;
}

int writeGradescopeZip(const fs::path& zip, const Context& context) {
    std::vector<ZipEntry> entries{{"setup.sh", {}, gradescopeSetupScript(), true},
                                  {"run_autograder", {}, gradescopeRunScript(), true}};
    const fs::path source = fs::canonical(build::kSourceDir);
    for (const TreeFile& file : studentTreeFiles(source)) {
        if (file.relative.begin()->string() == "third_party") continue; // written again below
        const fs::perms perms = fs::status(file.source).permissions();
        entries.push_back({"raylab/" + file.relative.generic_string(), file.source, {},
                           (perms & fs::perms::owner_exec) != fs::perms::none});
    }
    for (ZipEntry& e : thirdPartyEntries()) entries.push_back(std::move(e));
    for (ZipEntry& e : referenceLabEntries(source, loadLabCatalog(labsFolder(), context.scenes))) entries.push_back(std::move(e));
    if (zip.has_parent_path()) fs::create_directories(zip.parent_path());
    writeZip(zip, entries);
    std::printf("%s\n", tr("autograder.zip_written", {{"zip", zip.string()}, {"files", std::to_string(entries.size() - 2)}}).c_str());
    return 0;
}
#endif

int writeClassroomTree(const fs::path& out, const Context& context) {
    const LabCatalog catalog = loadLabCatalog(labsFolder(), context.scenes);
    const std::string workflowText = classroomWorkflow(catalog); // refuses points Classroom cannot count, before any file
    const int files = writeStudentTree(build::kSourceDir, out);
    const fs::path workflow = out / ".github" / "workflows" / "classroom.yml";
    fs::create_directories(workflow.parent_path());
    writeFileAtomically(workflow, workflowText);
    std::printf("%s\n", tr("autograder.classroom_written",
                            {{"files", std::to_string(files)},
                             {"workflow", workflow.lexically_relative(out).generic_string()},
                             {"steps", std::to_string(classroomSteps(catalog).size())},
                             {"folder", out.string()}})
                             .c_str());
    return 0;
}
#endif

// Gradescope's display fields, added to the results.json `raylab grade` wrote: its texts are plain
// text (Gradescope's default would read them as simple_format), and the run's duration in seconds.
// False when the file is not a JSON object (then nothing is kept).
bool addGradescopeFields(const fs::path& resultsJson, double seconds) {
    nlohmann::json results;
    try {
        std::ifstream in(resultsJson);
        results = nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception&) {
        return false;
    }
    if (!results.is_object()) return false;
    results["output_format"] = "text";
    results["test_output_format"] = "text";
    results["execution_time"] = std::max(0L, std::lround(seconds));
    writeFileAtomically(resultsJson, results.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    return true;
}

// What `raylab grade` hands over: a folder made by mkdtemp (mode 0700, ours), which the code graded
// (another user, in the fallback sandbox) can neither read nor write. Removed with what it holds.
class HandOver {
public:
    HandOver() {
        std::string pattern = (fs::temp_directory_path() / "raylab-autograder-XXXXXX").string();
#ifdef _WIN32 // no other user's code runs there (no sandbox either)
        pattern.replace(pattern.size() - 6, 6, std::to_string(std::random_device{}()));
        if (!fs::create_directory(pattern))
            throw std::runtime_error(tr("autograder.no_handover", {{"folder", pattern}}));
#else
        if (mkdtemp(pattern.data()) == nullptr)
            throw std::runtime_error(tr("autograder.no_handover", {{"folder", pattern}}));
#endif
        m_folder = pattern;
    }
    ~HandOver() {
        std::error_code ignored;
        fs::remove_all(m_folder, ignored);
    }
    HandOver(const HandOver&) = delete;
    HandOver& operator=(const HandOver&) = delete;
    const fs::path& folder() const { return m_folder; }

private:
    fs::path m_folder;
};

// raylab grade's results count only when it exited on its own: 0 (all passed), 1 (not all), 3
// (nothing written yet). Killed, crashed or stopped with an error: whatever is on disk is no result.
std::string whyNoResult(const ProcessResult& ran) {
    if (!ran.started) return tr("autograder.grade_not_started", {{"why", ran.error}});
    if (ran.signal != 0) return tr("autograder.grade_killed", {{"signal", std::to_string(ran.signal)}});
    if (ran.exitCode != 0 && ran.exitCode != 1 && ran.exitCode != 3)
        return tr("autograder.grade_stopped", {{"status", std::to_string(ran.exitCode)}});
    return {};
}

// Inside Gradescope's container: the submission's labs into the tree, `raylab grade --labs` on them
// (its own process), its results.json handed over in a folder of ours, then into results/ whole.
// Anything else (killed, crashed, a results.json that appeared elsewhere) is a zero with the reason.
int runGradescope(const Context& context) {
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    const fs::path root = autograderRoot(), results = root / "results";
    const fs::path tree = build::kSourceDir, submitted = tree / "submission";
    fs::create_directories(results);
    std::error_code error;
    fs::remove(results / "results.json", error);
    if (const std::string kind = sandboxKind(SandboxLimits{}); kind == "process group")
        std::printf("%s\n", tr("autograder.not_confined").c_str());
    std::string why;
    try {
        const HandOver handOver;
        const fs::path handed = handOver.folder() / "results.json";
        const LabCatalog catalog = loadLabCatalog(labsFolder(), context.scenes);
        copySubmittedLabs(root / "submission", catalog, submitted);
        std::fflush(stdout); // what we printed comes before what it prints
        const ProcessResult ran = runProcess({(fs::path(build::kBinaryDir) / "raylab").string(), "grade", "--labs",
                                              submitted.string(), "--build-dir", (tree / "build").string(), "--report",
                                              handOver.folder().string()});
        why = whyNoResult(ran);
        if (why.empty() && fs::exists(handed, error) && addGradescopeFields(handed, elapsed())) {
            const std::optional<std::string> graded = readWholeFile(handed);
            if (!graded) throw std::runtime_error(tr("autograder.no_results"));
            writeFileAtomically(results / "results.json", *graded);
            return 0;
        }
        if (why.empty()) why = tr("autograder.no_results");
    } catch (const std::exception& e) {
        why = e.what();
    }
    std::printf("raylab autograder run: %s\n", why.c_str());
    const HandOver scratch;
    GradeResult nothing =
        gradeBuildFailure(loadGradeSetup(referenceFolders(""), labsFolder(), context.scenes, scratch.folder()), why);
    writeGradescopeJson(nothing, results / "results.json");
    addGradescopeFields(results / "results.json", elapsed());
    return 0;
}

} // namespace

void addAutograderCommand(CLI::App& app, Context& context) {
    CLI::App* autograder = app.add_subcommand("autograder", tr("cli.autograder"));
    autograder->require_subcommand(1);

#ifndef RAYLAB_GRADING_ONLY
#ifndef RAYLAB_NO_GRADESCOPE_ZIP
    auto zip = std::make_shared<std::string>();
    CLI::App* gradescope =
        autograder->add_subcommand("gradescope", tr("cli.autograder_gradescope"));
    gradescope->add_option(tr("cli.type.FILE") + ".zip", *zip, tr("cli.autograder_zip"))->required();
    gradescope->callback([&context, zip] { context.exitStatus = writeGradescopeZip(*zip, context); });
#endif

    auto out = std::make_shared<std::string>();
    CLI::App* github = autograder->add_subcommand("github", tr("cli.autograder_github"));
    github->add_option(tr("cli.type.DIR"), *out, tr("cli.new_folder"))->required();
    github->callback([&context, out] { context.exitStatus = writeClassroomTree(*out, context); });
#endif

    CLI::App* run = autograder->add_subcommand("run", tr("cli.autograder_run"));
    run->callback([&context] { context.exitStatus = runGradescope(context); });
}

} // namespace raylab::cli
