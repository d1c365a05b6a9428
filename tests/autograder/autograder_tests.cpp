// The autograders end to end (tests/autograder/CMakeLists.txt makes the fixtures): Gradescope's zip
// unpacked into a /autograder-like folder, setup.sh run without its package installation, and
// run_autograder on the reference, the stubs, a catalogued mistake, a crash and an empty hand-in,
// each results.json checked against Gradescope's format and against `raylab grade` on the same code;
// GitHub Classroom's workflow parsed, its item steps' commands run in the built tree.
#include "support/files.h"
#include "support/needs.h"
#include "grader/course/autograder.h"
#include "grader/course/grade_reports.h"
#include "src/messages.h"
#include "grading_support.h"

#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>
#include <zip.h>

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace raylab::test;

namespace {

const fs::path kRoot = RAYLAB_AUTOGRADER_TEST_ROOT; // autograder.zip, autograder/ (Gradescope's), github/
fs::path autograder() { return kRoot / "autograder"; }
fs::path tree() { return autograder() / "source" / "raylab"; }

using raylab::test::readFile;

// A shell command's exit status, its output in `log`.
int run(const std::string& command, const fs::path& log) {
    const int raw = std::system((command + " > \"" + log.string() + "\" 2>&1").c_str());
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

void extractZip(const fs::path& zipFile, const fs::path& into) {
    int code = 0;
    zip_t* archive = zip_open(zipFile.string().c_str(), ZIP_RDONLY, &code);
    REQUIRE_MESSAGE(archive != nullptr, "cannot open " << zipFile << " (libzip error " << code << ")");
    const zip_int64_t count = zip_get_num_entries(archive, 0);
    for (zip_uint64_t k = 0; k < zip_uint64_t(count); ++k) {
        const std::string name = zip_get_name(archive, k, 0);
        zip_stat_t stat;
        zip_stat_index(archive, k, 0, &stat);
        std::string content(stat.size, '\0');
        zip_file_t* file = zip_fopen_index(archive, k, 0);
        REQUIRE(file != nullptr);
        CHECK(zip_fread(file, content.data(), stat.size) == zip_int64_t(stat.size));
        zip_fclose(file);
        const fs::path target = into / name;
        fs::create_directories(target.parent_path());
        std::ofstream(target, std::ios::binary) << content;
        zip_uint8_t system = 0;
        zip_uint32_t attributes = 0;
        zip_file_get_external_attributes(archive, k, 0, &system, &attributes);
        if (system == ZIP_OPSYS_UNIX) fs::permissions(target, fs::perms((attributes >> 16) & 0777));
    }
    zip_close(archive);
}

bool isVisibility(const nlohmann::json& v) {
    return v.is_string() && (v == "visible" || v == "hidden" || v == "after_due_date" || v == "after_published");
}

// Gradescope's results.json: the documented fields with their types; the total is the tests' sum;
// no leaderboard.
nlohmann::json validResults(const fs::path& file) {
    REQUIRE_MESSAGE(fs::exists(file), file << " was not written");
    const nlohmann::json j = nlohmann::json::parse(readFile(file));
    REQUIRE(j.is_object());
    REQUIRE(j["score"].is_number());
    CHECK(j["output"].is_string());
    CHECK(isVisibility(j["visibility"]));
    CHECK(isVisibility(j["stdout_visibility"]));
    CHECK_FALSE(j.contains("leaderboard"));
    // Plain text (Gradescope would read simple_format), and how long the run took, in whole seconds.
    CHECK(j["output_format"] == "text");
    CHECK(j["test_output_format"] == "text");
    CHECK(j["execution_time"].is_number_integer());
    CHECK(j["execution_time"].get<long>() >= 0);
    REQUIRE(j["tests"].is_array());
    double sum = 0.;
    for (const nlohmann::json& t : j["tests"]) {
        REQUIRE(t["score"].is_number());
        REQUIRE(t["max_score"].is_number());
        CHECK(t["name"].is_string());
        CHECK(t["output"].is_string());
        CHECK(isVisibility(t["visibility"]));
        CHECK((t["status"] == "passed" || t["status"] == "failed"));
        CHECK(t["score"].get<double>() <= t["max_score"].get<double>());
        sum += t["score"].get<double>();
    }
    CHECK(j["score"].get<double>() == doctest::Approx(sum));
    return j;
}

// The names of the regular files under `folder` whose names end with `ending`, relative to it.
std::set<std::string> filesNamed(const fs::path& folder, const std::string& ending) {
    std::set<std::string> names;
    std::error_code error;
    for (auto it = fs::recursive_directory_iterator(folder, error); it != fs::recursive_directory_iterator(); ++it) {
        const std::string name = it->path().filename().string();
        if (it->is_regular_file() && name.size() >= ending.size() && name.compare(name.size() - ending.size(), ending.size(), ending) == 0)
            names.insert(it->path().lexically_relative(folder).generic_string());
    }
    return names;
}

// Hands `folder` in as the submission (its content at the submission's top) and runs run_autograder,
// its environment changed by `environment` (shell assignments: `PATH=...`).
nlohmann::json gradeOnGradescope(const fs::path& folder, const std::string& environment = "") {
    fs::remove_all(autograder() / "submission");
    fs::copy(folder, autograder() / "submission", fs::copy_options::recursive);
    const fs::path log = kRoot / "run_autograder.log";
    CHECK_MESSAGE(run("cd \"" + autograder().string() + "\" && " + environment + " \"" +
                          (autograder() / "run_autograder").string() + "\"",
                      log) == 0,
                  readFile(log));
    return validResults(autograder() / "results" / "results.json");
}

// The solutions with the files of an applied patch (tests/grading/CMakeLists.txt) laid over them.
fs::path patchedSolutions(const std::string& kind, const std::string& id, const fs::path& labs) {
    fs::remove_all(labs);
    fs::create_directories(labs);
    fs::copy(sourceDir() / "solutions", labs, fs::copy_options::recursive);
    fs::copy(fs::path(RAYLAB_SUBMISSIONS) / kind / id, labs,
             fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    fs::remove(labs / "applied.stamp");
    return labs;
}

// Each item's points as results.json names it, from Gradescope's and from grading the agent here.
std::map<std::string, double> pointsByItem(const nlohmann::json& results) {
    std::map<std::string, double> points;
    for (const nlohmann::json& t : results["tests"]) points[t["name"]] = t["score"];
    return points;
}

std::map<std::string, double> pointsOfAgent(const std::string& agent) {
    const fs::path file = kRoot / (agent + ".results.json");
    writeGradescopeJson(gradeAgent(courseSetup(), agent), file);
    return pointsByItem(nlohmann::json::parse(readFile(file)));
}

YAML::Node workflowSteps() {
    const YAML::Node workflow = YAML::LoadFile((kRoot / "github" / ".github" / "workflows" / "classroom.yml").string());
    return workflow["jobs"]["run-autograding-tests"]["steps"];
}

// The command of the workflow's step that grades `item`.
std::string stepCommand(const std::string& item) {
    for (const YAML::Node& step : workflowSteps())
        if (step["with"] && step["with"]["test-name"] && step["with"]["test-name"].as<std::string>() == item)
            return step["with"]["command"].as<std::string>();
    FAIL("no step grades " << item);
    return "";
}

} // namespace

TEST_SUITE("autograder setup") {

TEST_CASE("the Gradescope zip unpacks into source/ and its setup.sh builds the tree") {
    fs::remove_all(autograder());
    extractZip(kRoot / "autograder.zip", autograder() / "source");
    for (const char* script : {"setup.sh", "run_autograder"}) {
        const fs::path file = autograder() / "source" / script;
        REQUIRE(fs::exists(file));
        CHECK((fs::status(file).permissions() & fs::perms::owner_exec) != fs::perms::none);
        CHECK(readFile(file).find("set -euo pipefail") != std::string::npos);
    }
    // The course's reference labs travel in the zip, to be compiled once by setup.sh and deleted (a given
    // lab's reference is in framework/given/).
    std::set<std::string> references;
    for (const LabDescription& lab : courseSetup().labs.labs)
        for (const std::string& file : filesNamed(sourceDir() / "solutions" / lab.id, ".cpp")) references.insert(lab.id + "/" + file);
    CHECK(filesNamed(tree() / "solutions", ".cpp") == references);
    CHECK(missingReferences(tree()).empty());
    for (const auto& lab : fs::directory_iterator(tree() / "framework/grader/labs"))
        CHECK_MESSAGE(!fs::exists(lab.path() / "mistakes"), lab.path()); // patches against the solutions
    CHECK(fs::exists(tree() / "labs/lab1_first_image/lab.toml"));
    // The header-only libraries, each with its licence, for an image that lacks them (Ubuntu 22.04: toml++).
    for (const char* header : {"glm/include/glm/glm.hpp", "tomlplusplus/include/toml++/toml.h", "cli11/include/CLI/CLI.hpp",
                               "nlohmann_json/include/nlohmann/json.hpp", "stb/include/stb_image_write.h"}) {
        const fs::path file = tree() / "third_party" / header;
        CHECK_MESSAGE(fs::is_regular_file(file), file);
        const fs::path library = *fs::path(header).begin();
        CHECK_MESSAGE(filesNamed(tree() / "third_party" / library, "").size() >= 2, library << " has no licence beside its headers");
    }
    // Gradescope copies run_autograder to /autograder and runs it from there.
    fs::copy_file(autograder() / "source" / "run_autograder", autograder() / "run_autograder");
    const fs::path log = kRoot / "setup.log";
    REQUIRE_MESSAGE(run("bash \"" + (autograder() / "source" / "setup.sh").string() + "\"", log) == 0, readFile(log));
    CHECK(fs::exists(tree() / "build" / "bin" / "raylab"));
    CHECK(fs::exists(tree() / "build" / "bin" / "raylab-agent"));
    for (const LabDescription& lab : courseSetup().labs.labs)
        CHECK(fs::exists(tree() / "build" / "bin" / ("raylab-agent-lab" + std::to_string(lab.number))));
    // What grading needs only: no report kit, no tests; and no reference source is left to read.
    CHECK_FALSE(fs::exists(tree() / "build" / "framework" / "report"));
    CHECK_FALSE(fs::exists(tree() / "build" / "tests"));
    CHECK(filesNamed(tree() / "solutions", ".cpp").empty());
    CHECK_FALSE(filesNamed(tree() / "solutions", ".o").empty());
    // Without bubblewrap the code graded reads what anyone may read: not the reference objects and pictures.
    std::vector<fs::path> secrets{tree() / "solutions"};
    for (const LabDescription& lab : courseSetup().labs.labs)
        secrets.push_back(tree() / "framework" / "grader" / "labs" / lab.id / "references"); // each lab's
    for (const fs::path& secret : secrets) {
        CAPTURE(secret);
        REQUIRE(fs::exists(secret));
        CHECK((fs::status(secret).permissions() & fs::perms::others_all) == fs::perms::none);
    }
    for (const std::string& object : filesNamed(tree() / "solutions", ".o"))
        CHECK((fs::status(tree() / "solutions" / object).permissions() & fs::perms::others_all) == fs::perms::none);
}

} // TEST_SUITE

TEST_SUITE("autograder gradescope") {

TEST_CASE("run_autograder: the reference solutions in labs/ earn every point") {
    const fs::path submission = kRoot / "hand-in-reference";
    fs::remove_all(submission);
    fs::create_directories(submission);
    fs::copy(sourceDir() / "solutions", submission / "labs", fs::copy_options::recursive);
    const nlohmann::json j = gradeOnGradescope(submission);
    CHECK(j["score"].get<double>() == doctest::Approx(catalogTotal()));
    for (const nlohmann::json& t : j["tests"]) CHECK_MESSAGE(t["status"] == "passed", t.dump());
}

TEST_CASE("run_autograder: the stubs, lab folders at the top, earn zero and say not done yet") {
    const nlohmann::json j = gradeOnGradescope(sourceDir() / "labs");
    CHECK(j["score"].get<double>() == 0.);
    CHECK(j["tests"].size() > 20);
    for (const nlohmann::json& t : j["tests"])
        CHECK_MESSAGE(t["output"].get<std::string>().find("not done yet") != std::string::npos, t.dump());
}

TEST_CASE("run_autograder: a catalogued mistake in a wrapping folder loses its points, with the hint; "
          "the workflow's steps grade its items alone") {
    const std::string id = "fovy_not_halved";
    const fs::path submission = kRoot / "hand-in-mistake";
    fs::remove_all(submission);
    patchedSolutions("mistake", id, submission / "raylab-main" / "labs");
    const nlohmann::json j = gradeOnGradescope(submission);
    CHECK(j["score"].get<double>() < catalogTotal());
    // Lab 2's items as `raylab grade` grades the same code; the other labs, graded with lab 2's
    // reference, keep every point.
    const std::map<std::string, double> ofAgent = pointsOfAgent("raylab-mistake-" + id);
    for (const nlohmann::json& t : j["tests"]) {
        const std::string name = t["name"];
        if (name.rfind("lab2: ", 0) == 0) CHECK_MESSAGE(t["score"].get<double>() == ofAgent.at(name), name);
        else CHECK_MESSAGE(t["score"] == t["max_score"], name);
    }
    std::string hint;
    for (const Mistake& m : courseSetup().mistakes)
        if (m.id == id) hint = m.hint();
    REQUIRE_FALSE(hint.empty());
    const std::string check = "updateViewport: the viewport of the default camera";
    bool hinted = false;
    for (const nlohmann::json& t : j["tests"]) {
        if (t["name"] == "lab2: " + check) CHECK(t["score"] == 0.);
        hinted = hinted || t["output"].get<std::string>().find(hint) != std::string::npos;
    }
    CHECK_MESSAGE(hinted, "no test's output holds the hint: " << hint);

    // The tree's agent now holds this submission: GitHub Classroom's step commands, run there.
    const fs::path log = kRoot / "item.log";
    const std::string cd = "cd \"" + tree().string() + "\" && ";
    CHECK_MESSAGE(run(cd + stepCommand("lab1_gradient"), log) == 0, readFile(log));
    CHECK(readFile(log).find("PASS  lab1  figure lab1_gradient") != std::string::npos);
    CHECK_MESSAGE(run(cd + stepCommand(check), log) == 1, readFile(log));
    const std::string output = readFile(log);
    CHECK(output.find("FAIL  lab2  " + check) != std::string::npos);
    CHECK(output.find("Hint:") != std::string::npos);
    CHECK(output.find("generateRay") == std::string::npos); // that item alone
}

TEST_CASE("run_autograder: a lab that does not compile costs that lab alone") {
    // Each lab is linked with the others' reference (compiled by setup.sh): the labs that use the
    // broken one keep their points.
    const fs::path submission = kRoot / "hand-in-lab-broken";
    fs::remove_all(submission);
    copyCourseSolutions(submission / "labs");
    const LabDescription broken = usedLab(courseSetup().labs);
    const std::string file = broken.files().front();
    std::ofstream(submission / "labs" / broken.id / file, std::ios::app) << "\nint missing_semicolon = 1\n";
    const nlohmann::json j = gradeOnGradescope(submission);
    const double lost = labPoints(broken);
    REQUIRE(lost > 0.);
    CHECK(j["score"].get<double>() == doctest::Approx(catalogTotal() - lost));
    const std::string prefix = "lab" + std::to_string(broken.number) + ": ";
    for (const nlohmann::json& t : j["tests"]) {
        const bool ofBroken = t["name"].get<std::string>().rfind(prefix, 0) == 0;
        CHECK_MESSAGE(t["status"] == (ofBroken ? "failed" : "passed"), t.dump());
    }
    CHECK(j["output"].get<std::string>().find(file) != std::string::npos); // the compiler's message
}

TEST_CASE("run_autograder: a submission that crashes is graded, the crash costing only its items") {
    const fs::path submission = kRoot / "hand-in-crash";
    fs::remove_all(submission);
    patchedSolutions("bad", "crash", submission);
    const nlohmann::json j = gradeOnGradescope(submission);
    CHECK(j["score"].get<double>() > 0.);
    CHECK(j["score"].get<double>() < catalogTotal());
    CHECK(pointsByItem(j) == pointsOfAgent("raylab-bad-crash"));
}

TEST_CASE("run_autograder: where bubblewrap cannot start, a submission that forges results.json and kills the "
          "graders above it earns the points of the labs it did not touch, no more") {
    // A bwrap that fails as in Docker's default seccomp profile: the grader (root) falls back on an
    // unprivileged user, which can neither write the results nor signal the grader.
    const fs::path failing = kRoot / "failing-bwrap";
    fs::create_directories(failing);
    std::ofstream(failing / "bwrap") << "#!/bin/sh\nexit 1\n";
    fs::permissions(failing / "bwrap", fs::perms(0755));
    const fs::path submission = kRoot / "hand-in-forges-results";
    fs::remove_all(submission);
    patchedSolutions("bad", "forges_results", submission); // lab 1 forges and kills; the other labs are right
    const nlohmann::json j = gradeOnGradescope(submission, "PATH=\"" + failing.string() + ":$PATH\"");
    CHECK(j["output"].get<std::string>().find("forged") == std::string::npos);
    double lab1 = 0.;
    for (const nlohmann::json& t : j["tests"]) {
        const bool ofLab1 = t["name"].get<std::string>().rfind("lab1: ", 0) == 0;
        if (ofLab1) lab1 += t["max_score"].get<double>();
        CHECK_MESSAGE(t["status"] == (ofLab1 ? "failed" : "passed"), t.dump());
    }
    REQUIRE(lab1 > 0.);
    CHECK(j["score"].get<double>() == doctest::Approx(catalogTotal() - lab1));
    CHECK(readFile(kRoot / "run_autograder.log").find("unprivileged user") != std::string::npos); // the fallback said so
}

TEST_CASE("run_autograder: a grader killed after the code graded forged results.json gives zero for every item, "
          "with the reason") {
    // Not confined (RAYLAB_SANDBOX=none: the process group, as root), the code writes a results.json in
    // results/ and in every folder it guesses a grader hands over in, then SIGKILLs raylab grade: what
    // a killed grade left counts for nothing.
    const fs::path submission = kRoot / "hand-in-kills-grade";
    fs::remove_all(submission);
    patchedSolutions("bad", "forges_results_kills_grade", submission);
    const nlohmann::json j = gradeOnGradescope(submission, "RAYLAB_SANDBOX=none");
    CHECK(j["score"].get<double>() == 0.);
    const std::string output = j["output"].get<std::string>();
    CHECK(output.find("forged") == std::string::npos);
    CHECK_MESSAGE(output.find("the grader was killed (signal 9) before it handed over its results") != std::string::npos, output);
    REQUIRE(j["tests"].size() > 20);
    for (const nlohmann::json& t : j["tests"]) CHECK_MESSAGE(t["status"] == "failed", t.dump());
}

TEST_CASE("run_autograder: a hand-in without lab files gets zero, saying what to upload, never \"does not build\"") {
    const fs::path submission = kRoot / "hand-in-empty";
    fs::remove_all(submission);
    fs::create_directories(submission / "notes");
    std::ofstream(submission / "notes" / "README.txt") << "my labs are on my laptop\n";
    const nlohmann::json j = gradeOnGradescope(submission);
    CHECK(j["score"] == 0.);
    CHECK(j["tests"].size() > 20);
    CHECK(j.dump().find("no lab file found: upload the lab files (gradient.cpp, ") != std::string::npos);
    CHECK(j.dump().find("does not build") == std::string::npos);
}

} // TEST_SUITE

TEST_SUITE("autograder minimal system") {

// A Debian 12 made by mmdebstrap with nothing but a compiler, CMake, make and zlib: the least the zip
// promises to need. Made once (a few minutes, from the mirror of this machine's apt sources, or
// RAYLAB_DEBIAN_MIRROR) and kept in a fixed folder: later runs only unpack, set up and grade in it.
fs::path minimalDebian() {
    const fs::path root = "/var/tmp/raylab-debian12-minimal", made = root / ".raylab-made";
    if (fs::exists(made)) return root;
    const char* mirror = std::getenv("RAYLAB_DEBIAN_MIRROR");
    std::string source = mirror && *mirror ? mirror : "";
    for (const char* configured : {"/etc/apt/sources.list.d/debian.sources", "/etc/apt/sources.list"})
        if (source.empty() && fs::exists(configured) && !readFile(configured).empty()) source = configured;
    const fs::path partial = root.string() + ".partial", log = kRoot / "mmdebstrap.log";
    fs::remove_all(partial);
    REQUIRE_MESSAGE(run("mmdebstrap --variant=minbase --include=g++-11,cmake,make,zlib1g-dev bookworm \"" +
                            partial.string() + "\" " + source,
                        log) == 0,
                    readFile(log));
    fs::remove_all(root);
    fs::rename(partial, root);
    std::ofstream(made) << "made by tests/autograder (mmdebstrap: minbase, g++-11 cmake make zlib1g-dev)\n";
    return root;
}

// The fixture is one folder for every tree of this machine (clones, worktrees, and the bare roots of
// scripts/bare_machine_check.sh, which mount it): one run at a time unpacks and grades in it, the
// others wait for its lock.
class FixtureLock {
public:
    explicit FixtureLock(const fs::path& root) : m_fd(open((root / ".raylab-lock").c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644)) {
        REQUIRE_MESSAGE(m_fd >= 0, "cannot open " << (root / ".raylab-lock"));
        REQUIRE(flock(m_fd, LOCK_EX) == 0);
    }
    ~FixtureLock() { close(m_fd); }
    FixtureLock(const FixtureLock&) = delete;
    FixtureLock& operator=(const FixtureLock&) = delete;

private:
    int m_fd;
};

// `command` run inside `root` (chroot, as root), with an environment of its own.
int inChroot(const fs::path& root, const std::string& command, const fs::path& log) {
    return run("chroot \"" + root.string() + "\" /usr/bin/env -i PATH=/usr/bin:/bin HOME=/root LANG=C.UTF-8 " +
                   "RAYLAB_SKIP_PACKAGES=1 /bin/bash -c '" + command + "'",
               log);
}

TEST_CASE("Debian 12 with only g++-11, cmake, make and zlib: setup.sh builds, run_autograder gives every point") {
    // Skipped, not failed, without mmdebstrap or root (support/needs.h).
    if (geteuid() != 0) {
        MESSAGE("skipped: needs root (chroot), as in CI");
        return;
    }
    if (raylab::test::neededProgram("mmdebstrap", "mmdebstrap").empty()) return;
    const fs::path root = minimalDebian();
    const FixtureLock lock(root);
    // What the system offers is what the zip may count on: no library but zlib, no c++ but g++-11.
    CHECK_FALSE(fs::exists(root / "usr/include/glm"));
    CHECK_FALSE(fs::exists(root / "usr/include/toml++"));
    CHECK_FALSE(fs::exists(root / "usr/bin/c++"));
    CHECK(fs::exists(root / "usr/include/zlib.h"));
    const fs::path home = root / "autograder";
    fs::remove_all(home);
    extractZip(kRoot / "autograder.zip", home / "source");
    fs::copy_file(home / "source" / "run_autograder", home / "run_autograder");
    const fs::path log = kRoot / "minimal-setup.log";
    REQUIRE_MESSAGE(inChroot(root, "/autograder/source/setup.sh", log) == 0, readFile(log));
    CHECK(readFile(log).find("from third_party/tomlplusplus") != std::string::npos);
    fs::create_directories(home / "submission");
    fs::copy(sourceDir() / "solutions", home / "submission" / "labs", fs::copy_options::recursive);
    const fs::path runLog = kRoot / "minimal-run.log";
    CHECK_MESSAGE(inChroot(root, "cd /autograder && ./run_autograder", runLog) == 0, readFile(runLog));
    const nlohmann::json j = validResults(home / "results" / "results.json");
    CHECK_MESSAGE(j["score"].get<double>() == doctest::Approx(catalogTotal()), j["output"].get<std::string>());
    for (const nlohmann::json& t : j["tests"]) CHECK_MESSAGE(t["status"] == "passed", t.dump());
}

} // TEST_SUITE

TEST_SUITE("autograder github") {

TEST_CASE("classroom.yml: GitHub Classroom's shape, a build, a step per check and figure with its points") {
    CHECK_FALSE(fs::exists(kRoot / "github" / "solutions"));
    CHECK(missingReferences(kRoot / "github").empty());
    const YAML::Node workflow = YAML::LoadFile((kRoot / "github" / ".github" / "workflows" / "classroom.yml").string());
    // A push grades; so does a run started by hand (workflow_dispatch) or by Classroom (repository_dispatch).
    std::set<std::string> events;
    for (const YAML::Node& event : workflow["on"]) events.insert(event.as<std::string>());
    CHECK(events == std::set<std::string>{"push", "workflow_dispatch", "repository_dispatch"});
    const YAML::Node steps = workflowSteps();
    REQUIRE(steps.IsSequence());
    std::map<std::string, double> expected; // every item of the labs' descriptions, with its points
    for (const LabDescription& lab : courseSetup().labs.labs) {
        for (const LabCheck& c : lab.checks) // its step shows its title
            expected[raylab::tr(raylab::Language::En, "check_title." + c.id)] = c.points;
        for (const LabFigure& f : lab.figures) expected[f.id] = f.points;
    }
    std::map<std::string, double> graded;
    std::vector<std::string> ids;
    int builds = 0;
    YAML::Node reporter, upload;
    for (const YAML::Node& step : steps) {
        const std::string uses = step["uses"] ? step["uses"].as<std::string>() : "";
        const bool always = step["if"] && step["if"].as<std::string>() == "always()";
        if (step["run"] && step["run"].as<std::string>().find("cmake --build build") != std::string::npos) {
            ++builds;
            CHECK(ids.empty()); // before the items
            // Past a lab that does not compile, on every core, only what grading needs, without LTO.
            const std::string command = step["run"].as<std::string>();
            for (const char* part : {" -- -k", "-j \"$(nproc)\"", "-DRAYLAB_GRADING_ONLY=ON", "-DRAYLAB_LTO=OFF"})
                CHECK_MESSAGE(command.find(part) != std::string::npos, command << " lacks " << part);
        } else if (builds > 0) {
            CHECK_MESSAGE(always, "a step after the build that a failed build would skip: " << step["name"].as<std::string>());
        }
        if (uses == "classroom-resources/autograding-command-grader@v1") {
            const YAML::Node with = step["with"];
            for (const char* key : {"test-name", "setup-command", "command", "timeout", "max-score"})
                CHECK_MESSAGE(with[key], "a grader step without " << key);
            const std::string name = with["test-name"].as<std::string>();
            CHECK(with["command"].as<std::string>().rfind("build/bin/raylab grade --item ", 0) == 0);
            CHECK(with["timeout"].as<int>() > 0);
            graded[name] = with["max-score"].as<int>(); // the reporter reads it with parseInt
            ids.push_back(step["id"].as<std::string>());
        }
        if (uses == "classroom-resources/autograding-grading-reporter@v1") reporter = step;
        if (uses.rfind("actions/upload-artifact@", 0) == 0) upload = step;
    }
    CHECK(builds == 1);
    CHECK(graded == expected);
    REQUIRE(reporter);
    std::string runners;
    for (const std::string& id : ids) {
        runners += (runners.empty() ? "" : ",") + id;
        std::string variable = id + "_RESULTS";
        for (char& c : variable) c = char(std::toupper(static_cast<unsigned char>(c)));
        CHECK(reporter["env"][variable].as<std::string>() == "${{steps." + id + ".outputs.result}}");
    }
    CHECK(reporter["with"]["runners"].as<std::string>() == runners);
    REQUIRE(upload);
    CHECK(upload["with"]["path"].as<std::string>() == "out/report");
}

} // TEST_SUITE

TEST_SUITE("autograder units") {

TEST_CASE("a submission's lab files are found at its top, in labs/, in one wrapping folder or flat; links are not copied") {
    const LabCatalog catalog = courseSetup().labs;
    const fs::path root = kRoot / "layouts";
    fs::remove_all(root);
    for (const fs::path& labs : {root / "top", root / "inlabs" / "labs", root / "wrapped" / "raylab-main" / "labs",
                                 root / "wrappedtop" / "my-labs"}) {
        fs::create_directories(labs / "lab2_primary_rays");
        std::ofstream(labs / "lab2_primary_rays" / "perspective_camera.cpp") << "// mine\n";
    }
    fs::create_directories(root / "flat");
    std::ofstream(root / "flat" / "perspective_camera.cpp") << "// mine\n";
    fs::create_directories(root / "wrapped" / "__MACOSX" / "raylab-main" / "labs" / "lab2_primary_rays");
    std::ofstream(root / "wrapped" / "__MACOSX" / "raylab-main" / "labs" / "lab2_primary_rays" / "perspective_camera.cpp")
        << "resource fork\n";
    for (const char* layout : {"top", "inlabs", "wrapped", "wrappedtop", "flat"}) {
        CAPTURE(layout);
        copySubmittedLabs(root / layout, catalog, root / "copied");
        CHECK(readFile(root / "copied" / "lab2_primary_rays" / "perspective_camera.cpp") == "// mine\n");
        CHECK_FALSE(fs::exists(root / "copied" / "lab1_first_image"));
    }
    fs::create_directories(root / "none" / "a");
    copySubmittedLabs(root / "none", catalog, root / "copied");
    CHECK(fs::is_empty(root / "copied"));

    fs::remove(root / "top" / "lab2_primary_rays" / "perspective_camera.cpp");
    fs::create_symlink(sourceDir() / "solutions" / "lab2_primary_rays" / "perspective_camera.cpp",
                       root / "top" / "lab2_primary_rays" / "perspective_camera.cpp");
    copySubmittedLabs(root / "top", catalog, root / "copied");
    CHECK(fs::is_empty(root / "copied"));
}

TEST_CASE("one item alone: its lab, its verdict and points; an unknown name is refused") {
    const LabCatalog catalog = courseSetup().labs;
    CHECK(labOfItem(catalog, "lab1_gradient") == 1);
    CHECK(labOfItem(catalog, "default_viewport") == 2); // a check's id
    CHECK_THROWS_AS(labOfItem(catalog, "updateViewport: the viewport of the default camera"), std::invalid_argument); // its title
    CHECK_THROWS_AS(labOfItem(catalog, "no such check"), std::invalid_argument);
    GradeResult r;
    r.checks.push_back({2, "a", false, "expected 1, got 2. Hint: h", 0., 3.});
    r.checks.push_back({2, "b", true, "", 2., 2.});
    r.labs.push_back({2, 2., 5., {"a note"}});
    const GradeResult one = onlyItem(r, "b");
    REQUIRE(one.checks.size() == 1);
    CHECK(one.allPassed());
    REQUIRE(one.labs.size() == 1);
    CHECK(one.labs[0].maxPoints == 2.);
    CHECK_FALSE(onlyItem(r, "a").allPassed());
    CHECK_THROWS(onlyItem(r, "c"));
}

TEST_CASE("results.json speaks the grade's language: the items' names, the total and each lab's points") {
    GradeResult r;
    r.checks.push_back({3, "near_side", true, "", 2., 2.}); // shown by its title
    r.figures.push_back({});
    r.figures.back().lab = 3;
    r.figures.back().id = "lab3_flat";
    r.figures.back().maxPoints = 2.;
    r.labs.push_back({3, 2., 4., {}});
    const fs::path file = kRoot / "language.results.json";
    const auto written = [&](raylab::Language language) {
        raylab::setLanguage(language);
        writeGradescopeJson(r, file);
        return nlohmann::json::parse(readFile(file));
    };
    const nlohmann::json fr = written(raylab::Language::Fr);
    const nlohmann::json en = written(raylab::Language::En);
    const std::string nbsp = "\u00A0";
    CHECK(fr["tests"][0]["name"] == "TP 3" + nbsp + ": intersect" + nbsp + ": un rayon par le centre touche la face avant");
    CHECK(fr["tests"][1]["name"] == "TP 3" + nbsp + ": figure lab3_flat");
    CHECK(fr["output"].get<std::string>().rfind("total" + nbsp + ": 2 / 4\nTP 3" + nbsp + ": 2 / 4 points\n", 0) == 0);
    CHECK(en["tests"][0]["name"] == "lab3: intersect: a ray through the centre hits the near side");
    CHECK(en["tests"][1]["name"] == "lab3: figure lab3_flat");
    CHECK(en["output"].get<std::string>().rfind("total: 2 / 4\nlab 3: 2 / 4 points\n", 0) == 0);
}

TEST_CASE("GitHub Classroom: points that are not whole numbers are refused, naming the item") {
    LabCatalog catalog = courseSetup().labs;
    REQUIRE_FALSE(catalog.labs.at(1).checks.empty());
    CHECK_NOTHROW(classroomWorkflow(catalog));
    LabCheck& check = catalog.labs.at(1).checks.front();
    check.points = 0.5;
    const std::string named = "\"" + check.id + "\" is worth 0.5 points";
    CHECK_THROWS_WITH_AS(classroomWorkflow(catalog), doctest::Contains(named.c_str()), std::invalid_argument);
    CHECK_THROWS_WITH_AS(classroomWorkflow(catalog), doctest::Contains("whole number"), std::invalid_argument);
}

TEST_CASE("the step ids are unique and fit GitHub's ids; the commands quote the names") {
    const std::vector<ClassroomStep> steps = classroomSteps(courseSetup().labs);
    std::set<std::string> ids;
    for (const ClassroomStep& s : steps) {
        CHECK(ids.insert(s.id).second);
        CHECK(s.id.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-") == std::string::npos);
    }
    CHECK(classroomCommand({"x", "it's", "It's", 1.}) == "build/bin/raylab grade --item 'it'\\''s' --report out/item-report");
}

} // TEST_SUITE
