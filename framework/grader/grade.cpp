#include "grader/grade.h"

#include "grader/answers.h"

#include "raylab/image_io.h"
#include "raylab/messages.h"

#include <algorithm>
#include <array>
#include <fstream>
#include <map>
#include <random>

namespace raylab::grader {

namespace fs = std::filesystem;

namespace {

constexpr double kDefaultCheckPoints = 1.;
constexpr double kDefaultFigurePoints = 2.;

// "all" or "labN": names the folders of an agent's runs and of its pictures.
std::string agentName(const AgentPlan& plan) { return plan.lab ? "lab" + std::to_string(plan.lab) : "all"; }

protocol::Request requestFor(const GradeSetup& setup, const Item& item) {
    if (item.check) return protocol::CheckRequest{item.id, item.check->calls};
    return protocol::RenderRequest{item.id, fs::absolute(setup.scenes / (item.figure->id + ".toml")).string(), setup.seed,
                                   setup.threads};
}

// Runs one agent until every item is answered; an item that never got its answer (a crash, an
// endless loop, an exit) is failed with the reason and not sent again, so one bad function costs
// only itself.
Reported runUntilDone(const GradeSetup& setup, const AgentPlan& plan, bool withChecks = true) {
    Reported r;
    const fs::path scratch = fs::absolute(setup.scratch / ("agent-" + agentName(plan)));
    fs::remove_all(scratch);
    fs::create_directories(scratch);
    // The drawn cases come from a seed the child never sees: each grading draws new ones.
    const std::vector<FunctionCheck> checks =
        withChecks ? functionChecks((std::uint64_t(std::random_device{}()) << 32) ^ std::random_device{}()) : std::vector<FunctionCheck>{};
    std::vector<Item> items;
    for (const FunctionCheck& c : checks)
        if (plan.lab == 0 || c.lab == plan.lab) items.push_back({items.size() + 1, &c, nullptr, false});
    for (const FigureReference& f : setup.references.figures)
        if (plan.lab == 0 || f.lab == plan.lab) items.push_back({items.size() + 1, nullptr, &f, false});
    std::map<std::uint64_t, Item*> byId;
    for (Item& item : items) byId[item.id] = &item;
    Ledger ledger(r);
    for (int attempt = 0;; ++attempt) {
        std::vector<Item*> sent;
        std::string requests;
        for (Item& item : items)
            if (!item.resolved) {
                sent.push_back(&item);
                requests += protocol::serialize(requestFor(setup, item)) + "\n";
            }
        if (sent.empty()) return r;
        const AgentRun run =
            runAgent({plan.program, {}, scratch / ("run" + std::to_string(attempt)), {setup.scenes}, {}, requests}, setup.limits);
        if (!run.violations.empty()) { // a run that attacked the grader earns nothing, and is not run again
            for (Item* item : sent) ledger.fail(*item, "the code graded " + run.violations.front());
            for (const std::string& v : run.violations) r.problems.push_back(plan.program.filename().string() + " " + v);
            return r;
        }
        const bool hello = readRun(run.lines, sent, byId, ledger);
        const auto unanswered = std::find_if(sent.begin(), sent.end(), [](const Item* i) { return !i->resolved; });
        if (unanswered == sent.end()) continue;
        const std::string why = run.describe();
        const std::string errors = run.stderrTail.empty() ? "" : tr("grade.error_output", {{"tail", run.stderrTail}});
        const std::string program = plan.program.filename().string();
        if (!hello) { // it never started: another run would do the same
            r.problems.push_back(tr("grade.agent_silent", {{"program", program}, {"why", why}}) + errors);
            for (Item* item : sent) ledger.fail(*item, tr("grade.never_started", {{"program", program}, {"why", why}}));
            return r;
        }
        ledger.fail(**unanswered, tr((*unanswered)->check ? "grade.check_stopped" : "grade.figure_stopped", {{"why", why}}) + errors);
    }
}

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
    for (auto& [lab, outcome] : labs) result.labs.push_back(outcome);
}

void addCheck(const GradeSetup& setup, GradeResult& result, CheckOutcome c) {
    c.maxPoints = setup.labs.checkPoints(c.lab, c.name, kDefaultCheckPoints);
    c.points = c.passed ? c.maxPoints : 0.;
    result.checks.push_back(std::move(c));
}

FigureOutcome gradeImage(const GradeSetup& setup, const FigureReference& reference, const Image8& image, const fs::path& file);

// Reads and compares one picture; every way a file can be wrong is a reason of its own.
FigureOutcome gradePicture(const GradeSetup& setup, const FigureReference& reference, const fs::path& file) {
    FigureOutcome f;
    f.id = reference.id;
    f.lab = reference.lab;
    f.maxPoints = setup.labs.figurePoints(f.id, kDefaultFigurePoints);
    std::error_code error;
    if (!fs::exists(file, error)) {
        f.found = false;
        f.reason = tr("grade.picture_missing", {{"file", file.string()}});
        return f;
    }
    if (!fs::is_regular_file(file, error)) { // a pipe or a device would block the read, or never end
        f.reason = "not a PNG file: " + file.string() + " is not a regular file (a pipe, a device or a folder)";
        return f;
    }
    {
        std::ifstream in(file, std::ios::binary);
        std::array<char, 8> magic{};
        in.read(magic.data(), magic.size());
        static constexpr std::array<char, 8> kPng{'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n'};
        if (!in || magic != kPng) {
            f.reason = tr(in ? "grade.picture_not_png" : "grade.picture_empty", {{"file", file.string()}});
            return f;
        }
    }
    Image8 image;
    try {
        image = readImage(file);
    } catch (const std::exception& e) {
        f.reason = tr("grade.picture_unreadable", {{"what", e.what()}});
        return f;
    }
    return gradeImage(setup, reference, image, file);
}

// Compares a picture with its reference; `file` is where the report finds it.
FigureOutcome gradeImage(const GradeSetup& setup, const FigureReference& reference, const Image8& image, const fs::path& file) {
    FigureOutcome f;
    f.id = reference.id;
    f.lab = reference.lab;
    f.maxPoints = setup.labs.figurePoints(f.id, kDefaultFigurePoints);
    f.studentImage = file;
    f.verdict = compareImage(reference, image);
    f.passed = f.verdict.passed;
    f.reason = f.verdict.reason;
    f.points = f.passed ? f.maxPoints : 0.;
    return f;
}

// Every item of a lab at zero, because its code did not build.
void addUnbuiltLab(const GradeSetup& setup, GradeResult& result, int lab) {
    if (const LabDescription* description = setup.labs.lab(lab))
        for (const LabCheck& check : description->checks)
            addCheck(setup, result, CheckOutcome{lab, check.name, false, tr("grade.does_not_build"), 0., 0.});
    for (const FigureReference& reference : setup.references.figures) {
        if (reference.lab != lab) continue;
        FigureOutcome f;
        f.id = reference.id;
        f.lab = reference.lab;
        f.maxPoints = setup.labs.figurePoints(f.id, kDefaultFigurePoints);
        f.reason = tr("grade.does_not_build");
        result.figures.push_back(std::move(f));
    }
}

const LabOutcome* outcomeOf(const GradeResult& result, int lab) {
    for (const LabOutcome& l : result.labs)
        if (l.lab == lab) return &l;
    return nullptr;
}

bool hasFailures(const LabOutcome* lab) { return lab != nullptr && lab->points < lab->maxPoints; }

// Whether lab `lab` fails where no other failing lab can be the cause: a failed check or figure that
// uses no lab with failures. A lab whose every failure runs a failing earlier lab's code is not
// worth fixing first (lab 3's figures through a lab 2 stub, say).
bool hasOwnFailures(const LabCatalog& catalog, const GradeResult& result, int lab) {
    const LabDescription* description = catalog.lab(lab);
    // An item no description names counts as the lab's own.
    const auto own = [&](const auto* item) {
        return item == nullptr || std::none_of(item->uses.begin(), item->uses.end(), [&](int other) {
                   return hasFailures(outcomeOf(result, other));
               });
    };
    return std::any_of(result.figures.begin(), result.figures.end(),
                       [&](const FigureOutcome& f) {
                           return f.lab == lab && !f.passed && own(description ? description->figure(f.id) : nullptr);
                       }) ||
           std::any_of(result.checks.begin(), result.checks.end(), [&](const CheckOutcome& c) {
               return c.lab == lab && !c.passed && own(description ? description->check(c.name) : nullptr);
           });
}

// Whether a failure of lab `lab` can come from lab `other`: a failed figure or check of `lab`
// whose description says it runs `other`'s code, while `other` has failures of its own.
bool failsThrough(const LabCatalog& catalog, const GradeResult& result, int lab, int other) {
    const LabDescription* description = catalog.lab(lab);
    if (description == nullptr || !hasFailures(outcomeOf(result, lab)) || !hasOwnFailures(catalog, result, other))
        return false;
    const auto uses = [other](const std::vector<int>& labs) { return std::find(labs.begin(), labs.end(), other) != labs.end(); };
    const bool figure = std::any_of(result.figures.begin(), result.figures.end(), [&](const FigureOutcome& f) {
        const LabFigure* item = description->figure(f.id);
        return f.lab == lab && !f.passed && item != nullptr && uses(item->uses);
    });
    const bool check = std::any_of(result.checks.begin(), result.checks.end(), [&](const CheckOutcome& c) {
        const LabCheck* item = description->check(c.name);
        return c.lab == lab && !c.passed && item != nullptr && uses(item->uses);
    });
    return figure || check;
}

// "lab 3 uses lab 2, which has failures: fix lab 2 first". When two labs use each other and both
// fail through the other, only the later lab is told to fix the earlier one (the course's order).
void addDependencyNotes(const LabCatalog& catalog, GradeResult& result) {
    for (LabOutcome& lab : result.labs) {
        const LabDescription* description = catalog.lab(lab.lab);
        if (description == nullptr) continue;
        for (int other : description->uses) {
            if (!failsThrough(catalog, result, lab.lab, other)) continue;
            if (other > lab.lab && failsThrough(catalog, result, other, lab.lab)) continue; // said the other way
            lab.notes.push_back(
                tr("grade.uses_failing_lab", {{"lab", std::to_string(lab.lab)}, {"other", std::to_string(other)}}));
        }
    }
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
        if (image.width == reference->image.width && image.height == reference->image.height)
            f.diagnosis = diagnose(setup.mistakes, f.id, image, reference->image, suspect).text();
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

GradeSetup loadGradeSetup(const fs::path& references, const fs::path& labs, const fs::path& scenes,
                          const fs::path& scratch) {
    GradeSetup setup;
    setup.references = loadReferences(references);
    setup.mistakes = loadMistakes(references);
    setup.labs = loadLabCatalog(labs, scenes);
    setup.scenes = scenes;
    setup.scratch = scratch;
    return setup;
}

GradeResult gradeCode(const GradeSetup& setup, const std::vector<AgentPlan>& agents, bool isolated,
                      const std::vector<int>& unbuilt, const std::string& buildMessage) {
    GradeResult result;
    if (!unbuilt.empty()) {
        std::string labs;
        for (int lab : unbuilt) labs.append(" ").append(std::to_string(lab));
        result.problems.push_back(tr("grade.labs_do_not_build", {{"labs", labs}}) + "\n" + buildMessage);
    }
    std::map<int, const AgentPlan*> agentOfLab;
    const std::vector<int> labs = setup.labs.numbers();
    for (const AgentPlan& plan : agents)
        for (int lab : labs)
            if (plan.lab == 0 || plan.lab == lab) agentOfLab[lab] = &plan;
    std::map<const AgentPlan*, Reported> reports;
    for (const AgentPlan& plan : agents) {
        reports[&plan] = runUntilDone(setup, plan);
        for (const std::string& p : reports[&plan].problems) result.problems.push_back(p);
    }
    for (int lab : labs) {
        const auto planIt = agentOfLab.find(lab);
        if (std::find(unbuilt.begin(), unbuilt.end(), lab) != unbuilt.end()) {
            addUnbuiltLab(setup, result, lab);
            continue;
        }
        if (planIt == agentOfLab.end()) continue;
        const AgentPlan& plan = *planIt->second;
        Reported& r = reports[&plan];
        // Every check reported, in the order it ran; then every check the table names that was
        // never reported, failed.
        for (const std::string& name : r.order)
            if (r.checks[name].lab == lab) addCheck(setup, result, r.checks[name]);
        if (const LabDescription* description = setup.labs.lab(lab))
            for (const LabCheck& check : description->checks)
                if (!r.checks.count(check.name))
                    addCheck(setup, result, CheckOutcome{lab, check.name, false, tr("grade.check_never_ran"), 0., 0.});
        for (const FigureReference& reference : setup.references.figures) {
            if (reference.lab != lab) continue;
            const auto it = r.figures.find(reference.id);
            FigureOutcome f;
            if (it != r.figures.end() && it->second.image) {
                // Kept for the report in a folder of the parent's, written after the agent is gone.
                const fs::path file = setup.scratch / ("figures-" + agentName(plan)) / (reference.id + ".png");
                fs::create_directories(file.parent_path());
                writePng(file, *it->second.image);
                f = gradeImage(setup, reference, *it->second.image, file);
            } else {
                f.id = reference.id;
                f.lab = lab;
                f.maxPoints = setup.labs.figurePoints(f.id, kDefaultFigurePoints);
                f.reason = it == r.figures.end() ? tr("grade.figure_never_ran") : it->second.reason;
            }
            result.figures.push_back(std::move(f));
        }
    }
    scoreLabs(setup.labs, result);
    addDiagnoses(setup, result, isolated);
    if (isolated)
        for (LabOutcome& lab : result.labs) lab.notes.push_back(tr("grade.graded_alone"));
    else
        addDependencyNotes(setup.labs, result);
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
