#include "grader/course/autograder.h"

#include "grader/course/submission_copy.h"

#include <nlohmann/json.hpp>
#include <zip.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <set>
#include <stdexcept>

namespace raylab::grader {

namespace fs = std::filesystem;

namespace {

// A double-quoted YAML scalar: JSON's string syntax is a subset of YAML's.
std::string yamlString(const std::string& text) { return nlohmann::json(text).dump(); }

std::string stepId(int lab, const std::string& name, std::set<std::string>& taken) {
    std::string id = "lab" + std::to_string(lab) + "-";
    for (char c : name) {
        const bool word = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
        if (word) id += c;
        else if (c >= 'A' && c <= 'Z') id += char(c - 'A' + 'a');
        else if (id.back() != '-') id += '-';
        if (id.size() >= 48) break;
    }
    while (id.back() == '-') id.pop_back();
    std::string unique = id;
    for (int k = 2; !taken.insert(unique).second; ++k) unique = id + "-" + std::to_string(k);
    return unique;
}

std::string upper(std::string text) {
    for (char& c : text)
        if (c >= 'a' && c <= 'z') c = char(c - 'a' + 'A');
    return text;
}

// POSIX shell single quotes: everything literal, a quote written '\''.
std::string shellQuote(const std::string& text) {
    std::string quoted = "'";
    for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

struct ZipArchive {
    zip_t* archive = nullptr;
    ~ZipArchive() {
        if (archive) zip_discard(archive);
    }
};

[[noreturn]] void zipFailure(zip_t* archive, const std::string& what) {
    throw std::runtime_error(what + ": " + zip_strerror(archive));
}

} // namespace

void copySubmittedLabs(const fs::path& submission, const LabCatalog& catalog, const fs::path& destination) {
    copySubmission(submission, catalog, destination);
}

int labOfItem(const LabCatalog& catalog, const std::string& item) {
    for (const LabDescription& lab : catalog.labs)
        if (lab.check(item) || lab.figure(item)) return lab.number;
    throw std::invalid_argument("--item \"" + item +
                                "\": no check has that name and no figure that id (their list is in labs/*/lab.toml)");
}

GradeResult onlyItem(const GradeResult& result, const std::string& item) {
    GradeResult one;
    one.title = result.title + " --item " + item;
    one.problems = result.problems;
    for (const CheckOutcome& c : result.checks)
        if (c.name == item) one.checks.push_back(c);
    for (const FigureOutcome& f : result.figures)
        if (f.id == item) one.figures.push_back(f);
    if (one.checks.empty() && one.figures.empty()) // never a pass for want of a verdict
        throw std::runtime_error("the grade has no verdict for \"" + item + "\"");
    for (const LabOutcome& lab : result.labs) {
        LabOutcome kept{lab.lab, 0., 0., lab.notes};
        for (const CheckOutcome& c : one.checks)
            if (c.lab == lab.lab) kept.points += c.points, kept.maxPoints += c.maxPoints;
        for (const FigureOutcome& f : one.figures)
            if (f.lab == lab.lab) kept.points += f.points, kept.maxPoints += f.maxPoints;
        if (kept.maxPoints > 0.) one.labs.push_back(kept);
    }
    return one;
}

std::vector<ClassroomStep> classroomSteps(const LabCatalog& catalog) {
    std::vector<ClassroomStep> steps;
    std::set<std::string> taken;
    for (const LabDescription& lab : catalog.labs) {
        for (const LabCheck& c : lab.checks) steps.push_back({stepId(lab.number, c.name, taken), c.name, c.points});
        for (const LabFigure& f : lab.figures) steps.push_back({stepId(lab.number, f.id, taken), f.id, f.points});
    }
    return steps;
}

std::string classroomCommand(const ClassroomStep& step) {
    return "build/bin/raylab grade --item " + shellQuote(step.name) + " --report out/item-report";
}

std::string classroomWorkflow(const LabCatalog& catalog) {
    const std::vector<ClassroomStep> steps = classroomSteps(catalog);
    std::string yaml =
        "# Written by `raylab autograder github`: GitHub Classroom's autograding, one step per check and\n"
        "# figure of labs/*/lab.toml with its points (a step earns all or nothing), after one build.\n"
        "name: Autograding Tests\n"
        "'on':\n- push\n- repository_dispatch\n"
        "permissions:\n  checks: write\n  actions: read\n  contents: read\n"
        "jobs:\n  run-autograding-tests:\n    runs-on: ubuntu-latest\n"
        "    if: github.actor != 'github-classroom[bot]'\n    steps:\n"
        "    - name: Checkout code\n      uses: actions/checkout@v4\n"
        "    - name: Build\n      run: scripts/setup.sh && cmake --preset default -DBUILD_TESTING=OFF && cmake --build build\n";
    for (const ClassroomStep& s : steps) {
        char points[32];
        std::snprintf(points, sizeof points, "%g", s.points);
        yaml += "    - name: " + yamlString(s.name) + "\n      id: " + s.id +
                "\n      uses: classroom-resources/autograding-command-grader@v1\n      with:\n        test-name: " +
                yamlString(s.name) + "\n        setup-command: ''\n        command: " + yamlString(classroomCommand(s)) +
                "\n        timeout: 10\n        max-score: " + points + "\n";
    }
    yaml += "    - name: HTML report\n      if: always()\n      run: build/bin/raylab grade --report out/report || true\n"
            "    - name: Upload the HTML report\n      if: always()\n      uses: actions/upload-artifact@v4\n"
            "      with:\n        name: raylab-report\n        path: out/report\n"
            "    - name: Autograding Reporter\n      uses: classroom-resources/autograding-grading-reporter@v1\n"
            "      env:\n";
    std::string runners;
    for (const ClassroomStep& s : steps) {
        yaml += "        " + upper(s.id) + "_RESULTS: \"${{steps." + s.id + ".outputs.result}}\"\n";
        runners += (runners.empty() ? "" : ",") + s.id;
    }
    return yaml + "      with:\n        runners: " + runners + "\n";
}

fs::path autograderRoot() {
    const char* root = std::getenv(kAutograderRootVariable);
    return root && *root ? fs::path(root) : fs::path("/autograder");
}

std::string gradescopeSetupScript() {
    return R"script(#!/usr/bin/env bash
# Written by `raylab autograder gradescope`. Gradescope runs it once, when it builds the autograder's
# image: it installs the packages the students' tree needs, then builds raylab and the grading agent
# (the stubs standing in for a submission), so that each submission only recompiles its lab files.
# RAYLAB_AUTOGRADER_ROOT moves /autograder; RAYLAB_SKIP_PACKAGES=1 skips the installation.
set -euo pipefail
root="${RAYLAB_AUTOGRADER_ROOT:-/autograder}"
tree="$root/source/raylab"
if [ "${RAYLAB_SKIP_PACKAGES:-0}" != "1" ]; then
  "$tree/scripts/setup.sh"
fi
rm -rf "$tree/submission"
cp -R "$tree/labs" "$tree/submission"
# Without link-time optimisation, as raylab grade builds a submission: the same pictures, quicker links.
cmake -S "$tree" -B "$tree/build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF \
  -DRAYLAB_SUBMISSION_DIR="$tree/submission" -DRAYLAB_LTO=OFF
cmake --build "$tree/build" -j "$(nproc)"
)script";
}

std::string gradescopeRunScript() {
    return R"script(#!/usr/bin/env bash
# Written by `raylab autograder gradescope`. Gradescope runs it for each submission: raylab copies the
# lab folders of /autograder/submission into the tree, grades them with `raylab grade --labs` and
# writes /autograder/results/results.json (zero for every item, with the reason, when it cannot).
# RAYLAB_AUTOGRADER_ROOT moves /autograder.
set -euo pipefail
root="${RAYLAB_AUTOGRADER_ROOT:-/autograder}"
exec "$root/source/raylab/build/bin/raylab" autograder run
)script";
}

void writeZip(const fs::path& zip, const std::vector<ZipEntry>& entries) {
    std::random_device random;
    const fs::path temporary = zip.string() + ".tmp-" + std::to_string(random());
    int code = 0;
    ZipArchive archive;
    archive.archive = zip_open(temporary.string().c_str(), ZIP_CREATE | ZIP_TRUNCATE, &code);
    if (!archive.archive) {
        zip_error_t error;
        zip_error_init_with_code(&error, code);
        const std::string message = zip_error_strerror(&error);
        zip_error_fini(&error);
        throw std::runtime_error("cannot write " + temporary.string() + ": " + message);
    }
    for (const ZipEntry& e : entries) {
        zip_source_t* source = e.file.empty()
                                   ? zip_source_buffer(archive.archive, e.content.data(), e.content.size(), 0)
                                   : zip_source_file(archive.archive, e.file.string().c_str(), 0, -1);
        if (!source) zipFailure(archive.archive, e.name);
        const zip_int64_t index = zip_file_add(archive.archive, e.name.c_str(), source, ZIP_FL_ENC_UTF_8);
        if (index < 0) {
            zip_source_free(source);
            zipFailure(archive.archive, e.name);
        }
        const zip_uint32_t mode = 0100000u | (e.executable ? 0755u : 0644u); // a regular file
        if (zip_file_set_external_attributes(archive.archive, zip_uint64_t(index), 0, ZIP_OPSYS_UNIX, mode << 16) < 0)
            zipFailure(archive.archive, e.name);
    }
    if (zip_close(archive.archive) < 0) {
        const std::string message = zip_strerror(archive.archive);
        std::error_code error;
        fs::remove(temporary, error);
        throw std::runtime_error("cannot write " + zip.string() + ": " + message);
    }
    archive.archive = nullptr;
    fs::rename(temporary, zip);
}

} // namespace raylab::grader
