#include "grader/judge/grade.h"

#include "grader/judge/agent_session.h"
#include "grader/judge/checks/checks.h"
#include "grader/judge/failure_causes.h"

#include "raylab/image_io.h"
#include "src/messages.h"

#include <algorithm>
#include <array>
#include <fstream>
#include <map>

namespace raylab::grader {

namespace fs = std::filesystem;

namespace {

constexpr double kDefaultFigurePoints = 2.;

void scoreLabs(const LabCatalog& catalog, GradeResult& result) {
    std::map<int, LabOutcome> labs;
    for (const LabDescription& lab : catalog.labs) labs[lab.number].lab = lab.number;
    for (const CheckOutcome& c : result.checks) {
        labs[c.lab].points += c.points;
        labs[c.lab].maxPoints += c.maxPoints;
    }
    for (const FigureOutcome& f : result.figures) {
        labs[f.lab].points += f.points;
        labs[f.lab].maxPoints += f.maxPoints;
    }
    // A lab whose every item reached a stub (its own, or a lab's its figures use) is not started
    // (addNotStartedNotes says so).
    std::map<int, bool> started;
    for (const CheckOutcome& c : result.checks) started[c.lab] = started[c.lab] || c.stubLab == 0;
    for (const FigureOutcome& f : result.figures) started[f.lab] = started[f.lab] || f.stubLab == 0;
    for (auto& [lab, outcome] : labs) {
        if (const auto it = started.find(lab); it != started.end()) outcome.notStarted = !it->second;
        result.labs.push_back(outcome);
    }
}

void addCheck(const GradeSetup& setup, GradeResult& result, CheckOutcome c) {
    c.maxPoints = setup.labs.checkPoints(c.lab, c.name);
    c.points = c.passed ? c.maxPoints : 0.;
    result.checks.push_back(std::move(c));
}

// A figure at zero, with why.
FigureOutcome figureAtZero(const GradeSetup& setup, const FigureReference& reference, const std::string& reason) {
    FigureOutcome f;
    f.id = reference.id;
    f.lab = reference.lab;
    f.maxPoints = setup.labs.figurePoints(f.id, kDefaultFigurePoints);
    f.reason = reason;
    return f;
}

// Compares a picture with its reference; `file` is where the report finds it.
FigureOutcome gradeImage(const GradeSetup& setup, const FigureReference& reference, const Image8& image, const fs::path& file) {
    ImageVerdict verdict = compareImage(reference, image);
    FigureOutcome f = figureAtZero(setup, reference, verdict.reason);
    f.studentImage = file;
    f.passed = verdict.passed;
    f.verdict = std::move(verdict);
    f.points = f.passed ? f.maxPoints : 0.;
    return f;
}

// Reads and compares one picture; every way a file can be wrong is a reason of its own.
FigureOutcome gradePicture(const GradeSetup& setup, const FigureReference& reference, const fs::path& file) {
    std::error_code error;
    if (!fs::exists(file, error)) {
        FigureOutcome f = figureAtZero(setup, reference, tr("grade.picture_missing", {{"file", file.string()}}));
        f.found = false;
        return f;
    }
    if (!fs::is_regular_file(file, error)) // a pipe or a device would block the read, or never end
        return figureAtZero(setup, reference,
                            tr("grade.picture_not_file", {{"file", file.string()}}));
    {
        std::ifstream in(file, std::ios::binary);
        std::array<char, 8> magic{};
        in.read(magic.data(), magic.size());
        static constexpr std::array<char, 8> kPng{'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n'};
        if (!in || magic != kPng)
            return figureAtZero(setup, reference, tr(in ? "grade.picture_not_png" : "grade.picture_empty", {{"file", file.string()}}));
    }
    Image8 image;
    try {
        image = readImage(file);
    } catch (const std::exception& e) {
        return figureAtZero(setup, reference, tr("grade.picture_unreadable", {{"what", e.what()}}));
    }
    return gradeImage(setup, reference, image, file);
}

// "labs 2 4 do not build", with the compiler's message, when some do not.
void addBuildProblem(GradeResult& result, const std::vector<int>& unbuilt, const std::string& buildMessage) {
    if (unbuilt.empty()) return;
    std::string labs;
    for (int lab : unbuilt) labs.append(labs.empty() ? "" : " ").append(std::to_string(lab));
    result.problems.push_back(tr("grade.labs_do_not_build", {{"labs", labs}}) + "\n" + buildMessage);
}

// Every item of a lab at zero, because its code did not build.
void addUnbuiltLab(const GradeSetup& setup, GradeResult& result, int lab) {
    if (const LabDescription* description = setup.labs.lab(lab))
        for (const LabCheck& check : description->checks)
            addCheck(setup, result, CheckOutcome{lab, check.id, false, tr("grade.does_not_build"), 0., 0.});
    for (const FigureReference& reference : setup.references.figures)
        if (reference.lab == lab) result.figures.push_back(figureAtZero(setup, reference, tr("grade.does_not_build")));
}

// The agent that holds each lab's code: the last plan that covers it.
std::map<int, const AgentPlan*> agentsByLab(const std::vector<AgentPlan>& agents, const std::vector<int>& labs) {
    std::map<int, const AgentPlan*> agentOfLab;
    for (const AgentPlan& plan : agents)
        for (int lab : labs)
            if (plan.lab == 0 || plan.lab == lab) agentOfLab[lab] = &plan;
    return agentOfLab;
}

// Runs every agent, in order; what went wrong around their items goes to the result's problems.
std::map<const AgentPlan*, Reported> runAgents(const GradeSetup& setup, const std::vector<AgentPlan>& agents,
                                               GradeResult& result) {
    std::map<const AgentPlan*, Reported> reports;
    for (const AgentPlan& plan : agents) {
        const Reported& reported = reports[&plan] = runUntilDone(setup, plan);
        result.problems.insert(result.problems.end(), reported.problems.begin(), reported.problems.end());
    }
    return reports;
}

// Every check of the lab reported, in the order it ran; then every check its description names
// that was never reported, failed.
void addReportedChecks(const GradeSetup& setup, GradeResult& result, const Reported& reported, int lab) {
    for (const std::string& name : reported.order)
        if (reported.checks.at(name).lab == lab) addCheck(setup, result, reported.checks.at(name));
    if (const LabDescription* description = setup.labs.lab(lab))
        for (const LabCheck& check : description->checks)
            if (!reported.checks.count(check.id))
                addCheck(setup, result, CheckOutcome{lab, check.id, false, tr("grade.check_never_ran"), 0., 0.});
}

// Every figure of the lab as the agent rendered it, graded, or failed with why it has no picture.
void addReportedFigures(const GradeSetup& setup, GradeResult& result, const AgentPlan& plan, const Reported& reported,
                        int lab) {
    for (const FigureReference& reference : setup.references.figures) {
        if (reference.lab != lab) continue;
        const auto it = reported.figures.find(reference.id);
        if (it == reported.figures.end()) {
            result.figures.push_back(figureAtZero(setup, reference, tr("grade.figure_never_ran")));
        } else if (!it->second.image) {
            result.figures.push_back(figureAtZero(setup, reference, it->second.reason));
            result.figures.back().stubLab = it->second.stubLab;
            result.figures.back().stopped = it->second.stopped;
        } else {
            // Kept for the report in a folder of the parent's, written after the agent is gone.
            const fs::path file = setup.scratch / ("figures-" + agentName(plan)) / (reference.id + ".png");
            fs::create_directories(file.parent_path());
            writePng(file, *it->second.image);
            result.figures.push_back(gradeImage(setup, reference, *it->second.image, file));
        }
    }
}

// "nothing of lab 3 is written yet", last among a lab's notes.
void addNotStartedNotes(GradeResult& result) {
    for (LabOutcome& lab : result.labs)
        if (lab.notStarted) lab.notes.push_back(tr("grade.not_started", {{"lab", std::to_string(lab.lab)}}));
}

// Names the likely mistake of every failed figure, once every lab is scored. A suspect is a mistake
// of the figure's own lab, or of a lab it uses that has failures of its own (never one that came from
// the reference, as when each lab is graded alone), and whose check, when it ran, failed: so a lab
// whose code is right is never blamed, even for a picture its mistake would also draw.
void addDiagnoses(const GradeSetup& setup, GradeResult& result, bool isolated) {
    const auto checkPassed = [&result](const std::string& name) {
        return std::any_of(result.checks.begin(), result.checks.end(),
                           [&name](const CheckOutcome& c) { return c.name == name && c.passed; });
    };
    for (FigureOutcome& f : result.figures) {
        if (f.passed || f.studentImage.empty()) continue;
        const FigureReference* reference = setup.references.find(f.id);
        if (reference == nullptr) continue;
        std::vector<int> labs{f.lab};
        if (const LabFigure* figure = setup.labs.figure(f.id); figure != nullptr && !isolated)
            for (int other : figure->uses)
                if (hasOwnFailures(setup.labs, result, other)) labs.push_back(other);
        const auto suspect = [&](const Mistake& m) {
            return std::find(labs.begin(), labs.end(), m.lab) != labs.end() && !checkPassed(m.check);
        };
        Image8 image;
        try {
            image = readImage(f.studentImage);
        } catch (const std::exception&) {
            continue; // unreadable: its reason already says so
        }
        if (image.width != reference->image.width || image.height != reference->image.height) continue;
        const Diagnosis diagnosis = diagnose(setup.mistakes, f.id, image, reference->image, suspect);
        f.diagnosis = diagnosis.text();
        for (const Mistake* m : {diagnosis.mistake, diagnosis.alike})
            if (m != nullptr) f.mistakes.push_back(m->id);
    }
}

} // namespace

double GradeResult::score() const {
    double s = 0.;
    for (const LabOutcome& l : labs) s += l.points;
    return s;
}

double GradeResult::maxScore() const {
    double s = 0.;
    for (const LabOutcome& l : labs) s += l.maxPoints;
    return s;
}

bool GradeResult::allPassed() const {
    return std::all_of(checks.begin(), checks.end(), [](const auto& c) { return c.passed; }) &&
           std::all_of(figures.begin(), figures.end(), [](const auto& f) { return f.passed || !f.found; });
}

fs::path sceneFile(const GradeSetup& setup, const std::string& figure) {
    if (!setup.scenes.empty()) return setup.scenes / (figure + ".toml");
    const LabFigure* f = setup.labs.figure(figure);
    if (f == nullptr) throw std::logic_error("no lab lists the figure " + figure);
    return f->scene;
}

std::vector<fs::path> sceneFolders(const GradeSetup& setup) {
    if (!setup.scenes.empty()) return {setup.scenes};
    return sceneFolders(setup.labs);
}

GradeSetup loadGradeSetup(const std::vector<fs::path>& references, const fs::path& labs, const fs::path& scenes,
                          const fs::path& scratch) {
    GradeSetup setup;
    setup.references = loadReferences(references);
    setup.mistakes = loadMistakes(references);
    setup.labs = loadLabCatalog(labs, scenes);
    functionChecks(setup.labs, 0); // the checks of the code are those of lab.toml, or it throws naming both places
    for (const Mistake& m : setup.mistakes) // any number of labs: a mistake's lab is one that lab.toml describes
        if (setup.labs.lab(m.lab) == nullptr)
            throw std::runtime_error((m.folder / "mistakes.toml").string() + ": mistake '" + m.id + "' is of lab " +
                                     std::to_string(m.lab) + ", which no labs/*/lab.toml describes");
    setup.scenes = scenes;
    setup.scratch = scratch;
    return setup;
}

GradeResult gradeCode(const GradeSetup& setup, const std::vector<AgentPlan>& agents, bool isolated,
                      const std::vector<int>& unbuilt, const std::string& buildMessage) {
    GradeResult result;
    addBuildProblem(result, unbuilt, buildMessage);
    const std::vector<int> labs = setup.labs.numbers();
    const std::map<int, const AgentPlan*> agentOfLab = agentsByLab(agents, labs);
    const std::map<const AgentPlan*, Reported> reports = runAgents(setup, agents, result);
    for (int lab : labs) {
        const auto plan = agentOfLab.find(lab);
        if (std::find(unbuilt.begin(), unbuilt.end(), lab) != unbuilt.end())
            addUnbuiltLab(setup, result, lab);
        else if (plan != agentOfLab.end()) {
            addReportedChecks(setup, result, reports.at(plan->second), lab);
            addReportedFigures(setup, result, *plan->second, reports.at(plan->second), lab);
        }
    }
    scoreLabs(setup.labs, result);
    for (LabOutcome& lab : result.labs)
        lab.unbuilt = std::find(unbuilt.begin(), unbuilt.end(), lab.lab) != unbuilt.end();
    addDiagnoses(setup, result, isolated);
    if (isolated)
        for (LabOutcome& lab : result.labs) lab.notes.push_back(tr("grade.graded_alone"));
    else
        addDependencyNotes(setup.labs, result);
    addNotStartedNotes(result);
    return result;
}

std::map<std::string, Image8> renderFigures(const GradeSetup& setup, const fs::path& agent) {
    std::map<std::string, Image8> pictures;
    for (auto& [id, figure] : runUntilDone(setup, AgentPlan{agent, 0}, false).figures)
        if (figure.image) pictures[id] = std::move(*figure.image);
    return pictures;
}

GradeResult gradeImages(const GradeSetup& setup, const fs::path& folder) {
    GradeResult result;
    std::error_code error;
    if (!fs::is_directory(folder, error)) result.problems.push_back(tr("grade.no_folder", {{"folder", folder.string()}}));
    for (const FigureReference& reference : setup.references.figures)
        result.figures.push_back(gradePicture(setup, reference, folder / (reference.id + ".png")));
    if (fs::is_directory(folder, error))
        for (const auto& entry : fs::directory_iterator(folder))
            if (entry.path().extension() == ".png" && !setup.references.find(entry.path().stem().string()))
                result.problems.push_back(tr("grade.picture_ignored", {{"file", entry.path().filename().string()}}));
    scoreLabs(setup.labs, result);
    addDiagnoses(setup, result, false);
    return result;
}

GradeResult gradeBuildFailure(const GradeSetup& setup, const std::string& compilerMessage) {
    return gradeCode(setup, {}, false, setup.labs.numbers(), compilerMessage);
}

} // namespace raylab::grader
