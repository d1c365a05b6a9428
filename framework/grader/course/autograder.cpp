#include "grader/course/autograder.h"

#include "grader/course/submission_copy.h"
#include "src/messages.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
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

} // namespace

void copySubmittedLabs(const fs::path& submission, const LabCatalog& catalog, const fs::path& destination) {
    copySubmission(submission, catalog, destination);
}

int labOfItem(const LabCatalog& catalog, const std::string& item) {
    for (const LabDescription& lab : catalog.labs)
        if (lab.check(item) || lab.figure(item)) return lab.number;
    throw std::invalid_argument("--item \"" + item +
                                "\": no check and no figure has that id (their list is in labs/*/lab.toml)");
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
        for (const LabCheck& c : lab.checks)
            steps.push_back({stepId(lab.number, c.id, taken), c.id, tr(Language::En, "check_title." + c.id), c.points});
        for (const LabFigure& f : lab.figures) steps.push_back({stepId(lab.number, f.id, taken), f.id, f.id, f.points});
    }
    return steps;
}

std::string classroomCommand(const ClassroomStep& step) {
    return "build/bin/raylab grade --item " + shellQuote(step.name) + " --report out/item-report";
}

std::string classroomWorkflow(const LabCatalog& catalog) {
    const std::vector<ClassroomStep> steps = classroomSteps(catalog);
    for (const ClassroomStep& s : steps) // the reporter reads max-score with parseInt: 0.5 would count 0
        if (!std::isfinite(s.points) || s.points != std::floor(s.points) || s.points < 0.)
            throw std::invalid_argument(tr("autograder.points_not_integer", {{"item", s.name}, {"points", formatNumber(s.points, 6)}}));
    // Every step after the build runs `if: always()`: a lab that does not compile fails the build step
    // (built with -k, so the rest is built), and the items that were built are still graded.
    std::string yaml =
        "# Written by `raylab autograder github`: GitHub Classroom's autograding, one step per check and\n"
        "# figure of labs/*/lab.toml with its points (a step earns all or nothing), after one build.\n"
        "name: Autograding Tests\n"
        "'on':\n- push\n- workflow_dispatch\n- repository_dispatch\n"
        "permissions:\n  checks: write\n  actions: read\n  contents: read\n"
        "jobs:\n  run-autograding-tests:\n    runs-on: ubuntu-latest\n"
        "    if: github.actor != 'github-classroom[bot]'\n    steps:\n"
        "    - name: Checkout code\n      uses: actions/checkout@v4\n"
        "    - name: Build\n      run: " + yamlString(classroomBuildCommand()) + "\n";
    for (const ClassroomStep& s : steps) {
        yaml += "    - name: " + yamlString(s.title) + "\n      id: " + s.id +
                "\n      if: always()\n      uses: classroom-resources/autograding-command-grader@v1\n      with:\n        test-name: " +
                yamlString(s.title) + "\n        setup-command: ''\n        command: " + yamlString(classroomCommand(s)) +
                "\n        timeout: 10\n        max-score: " + std::to_string(std::lround(s.points)) + "\n";
    }
    yaml += "    - name: HTML report\n      if: always()\n      run: build/bin/raylab grade --report out/report || true\n"
            "    - name: Upload the HTML report\n      if: always()\n      uses: actions/upload-artifact@v4\n"
            "      with:\n        name: raylab-report\n        path: out/report\n"
            "    - name: Autograding Reporter\n      if: always()\n      uses: classroom-resources/autograding-grading-reporter@v1\n"
            "      env:\n";
    std::string runners;
    for (const ClassroomStep& s : steps) {
        yaml += "        " + upper(s.id) + "_RESULTS: \"${{steps." + s.id + ".outputs.result}}\"\n";
        runners += (runners.empty() ? "" : ",") + s.id;
    }
    return yaml + "      with:\n        runners: " + runners + "\n";
}

std::string classroomBuildCommand() {
    // Only what grading needs, without link-time optimisation, on every core; -k: past a lab that
    // does not compile, so that the others are built.
    return "scripts/setup.sh && cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF -DRAYLAB_GRADING_ONLY=ON "
           "-DRAYLAB_LTO=OFF && cmake --build build -j \"$(nproc)\" -- -k";
}

fs::path autograderRoot() {
    const char* root = std::getenv(kAutograderRootVariable);
    return root && *root ? fs::path(root) : fs::path("/autograder");
}

std::string gradescopeSetupScript() {
    return R"script(#!/usr/bin/env bash
# Written by `raylab autograder gradescope`. Gradescope runs it once, when it builds the autograder's
# image (Ubuntu 22.04 or newer, Debian 12): it installs a compiler, CMake, make and zlib when they are
# missing (the header-only libraries are in raylab/third_party/), compiles the reference labs once and
# deletes their sources, then builds what grading needs (raylab and the grading agents, the stubs
# standing in for a submission), without link-time optimisation, so that each submission only
# recompiles its lab files and each of its labs is linked with the others' reference.
# Where bubblewrap cannot start (Docker's default seccomp profile forbids its namespaces), the grader,
# root, runs the students' code as the user raylab-grader, created here, under a seccomp filter
# (libseccomp); the references and the reference objects are made unreadable to it.
# RAYLAB_AUTOGRADER_ROOT moves /autograder; RAYLAB_SKIP_PACKAGES=1 skips the installation and the user.
set -euo pipefail
root="${RAYLAB_AUTOGRADER_ROOT:-/autograder}"
tree="$root/source/raylab"
if [ "${RAYLAB_SKIP_PACKAGES:-0}" != "1" ]; then
  missing=()
  for package in cmake g++ make zlib1g-dev; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
  done
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  if ((${#missing[@]})); then apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null; fi
  # The grader's sandbox; without it (or where it cannot start) the grader confines the agents itself.
  apt-get install -y -qq --no-install-recommends bubblewrap >/dev/null || echo "setup.sh: bubblewrap could not be installed"
  # Its fallback: a seccomp filter (libseccomp, found by pkg-config) and a user with no home and no shell.
  apt-get install -y -qq --no-install-recommends pkg-config libseccomp-dev >/dev/null ||
    echo "setup.sh: libseccomp could not be installed: the fallback sandbox will have no seccomp filter"
  id raylab-grader >/dev/null 2>&1 || useradd --system --no-create-home --shell /usr/sbin/nologin raylab-grader ||
    echo "setup.sh: no user raylab-grader: the fallback sandbox will run the code as nobody"
fi
# A C++20 compiler: $CXX, else c++, else the newest g++ (11 or later) or clang++ (14 or later).
if [ -z "${CXX:-}" ] && ! command -v c++ >/dev/null; then
  for candidate in g++-14 g++-13 g++-12 g++-11 clang++-18 clang++-17 clang++-16 clang++-15 clang++-14; do
    if command -v "$candidate" >/dev/null; then export CXX="$candidate"; break; fi
  done
fi
rm -rf "$tree/submission"
cp -R "$tree/labs" "$tree/submission"
options=(-DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF -DRAYLAB_GRADING_ONLY=ON -DRAYLAB_LTO=OFF
         "-DRAYLAB_SUBMISSION_DIR=$tree/submission")
jobs="$(nproc)"
cmake -S "$tree" -B "$tree/build" "${options[@]}"
cmake --build "$tree/build" -j "$jobs" --target raylab-reference-objects
find "$tree/solutions" -name '*.cpp' -delete
cmake -S "$tree" -B "$tree/build" "${options[@]}"
cmake --build "$tree/build" -j "$jobs"
# Without bubblewrap the students' code sees every world-readable file: not these (root still reads them).
chmod -R go-rwx "$tree/solutions" "$tree"/framework/grader/labs/*/references
find "$tree/build" -type d -name 'raylab_lab*_solutions.dir' -exec chmod -R go-rwx {} +
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

} // namespace raylab::grader
