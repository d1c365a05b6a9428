#include "grader/grade.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <fstream>
#include <map>
#include <set>

namespace raylab::grader {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr double kDefaultCheckPoints = 1.;
constexpr double kDefaultFigurePoints = 2.;

bool isCheckItem(const std::string& item) { return item.rfind("figure ", 0) != 0; }

// What an agent reported, over all its runs.
struct Reported {
    std::map<std::string, CheckOutcome> checks; // by name
    std::vector<std::string> order;             // the names in the order the checks ran (their files' order)
    std::map<std::string, json> figures;        // by id: the agent's "figure" line
    std::vector<std::string> problems;
};

int labOfSuite(const std::string& suite) {
    return suite.size() == 4 && suite.rfind("lab", 0) == 0 ? suite[3] - '0' : 0;
}

// Runs one agent until it has said everything; a check or figure that started and never ended
// is failed with the reason and skipped on the next run, so one bad function costs only itself.
Reported runUntilDone(const GradeSetup& setup, const AgentPlan& plan) {
    Reported r;
    const fs::path scratch = fs::absolute(setup.scratch / ("agent-" + (plan.lab ? "lab" + std::to_string(plan.lab) : std::string("all"))));
    fs::remove_all(scratch);
    fs::create_directories(scratch);
    std::set<std::string> skip;
    for (int attempt = 0; attempt < 40; ++attempt) {
        {
            std::ofstream out(scratch / "skip.txt");
            for (const std::string& s : skip) out << s << "\n";
        }
        std::vector<std::string> args{"--checks", "--figures", fs::absolute(setup.scenes).string(), "--out",
                                      (scratch / "figures").string(), "--skip-file", (scratch / "skip.txt").string(),
                                      "--threads", std::to_string(setup.threads)};
        if (plan.lab) args.insert(args.end(), {"--lab", std::to_string(plan.lab)});
        if (setup.seed >= 0) args.insert(args.end(), {"--seed", std::to_string(setup.seed)});
        const AgentRun run = runAgent(plan.program, args, scratch / ("run" + std::to_string(attempt)), setup.limits);
        std::string pendingCheck, pendingFigure;
        int pendingLab = plan.lab;
        bool done = false;
        int progress = 0; // items finished in this run
        for (const std::string& line : run.lines) {
            const json j = json::parse(line, nullptr, false);
            if (!j.is_object()) continue; // not ours: ignored
            const std::string kind = j.value("kind", "");
            if (kind == "check-start") {
                pendingCheck = j.value("name", "");
                pendingLab = labOfSuite(j.value("suite", ""));
            } else if (kind == "check") {
                CheckOutcome c;
                c.lab = labOfSuite(j.value("suite", ""));
                c.name = j.value("name", "");
                c.passed = j.value("passed", false);
                c.message = j.value("message", "");
                if (c.lab != 0 && (plan.lab == 0 || c.lab == plan.lab) && !r.checks.count(c.name)) {
                    r.order.push_back(c.name);
                    r.checks[c.name] = c;
                }
                skip.insert(c.name);
                pendingCheck.clear();
                ++progress;
            } else if (kind == "figure-start") {
                pendingFigure = j.value("id", "");
            } else if (kind == "figure") {
                r.figures[j.value("id", "")] = j;
                skip.insert("figure:" + j.value("id", ""));
                pendingFigure.clear();
                ++progress;
            } else if (kind == "done") {
                done = true;
            }
        }
        if (done) return r;
        const std::string why = run.describe();
        if (!pendingCheck.empty()) {
            CheckOutcome c{pendingLab, pendingCheck, false, "this check " + why + (run.stderrTail.empty() ? "" : "; its error output ends with: " + run.stderrTail), 0., 0.};
            if (!r.checks.count(c.name)) r.order.push_back(c.name);
            r.checks[c.name] = c;
            skip.insert(c.name);
        } else if (!pendingFigure.empty()) {
            r.figures[pendingFigure] = json{{"kind", "figure"}, {"id", pendingFigure}, {"status", "failed"},
                                            {"message", "rendering " + why}};
            skip.insert("figure:" + pendingFigure);
        } else if (progress == 0) { // nothing new: another run would do the same
            r.problems.push_back(plan.program.filename().string() + " " + why + " before it had reported everything" +
                                 (run.stderrTail.empty() ? "" : ": " + run.stderrTail));
            return r;
        }
    }
    r.problems.push_back(plan.program.filename().string() + " was stopped after 40 restarts");
    return r;
}

void scoreLabs(GradeResult& result) {
    std::map<int, LabOutcome> labs;
    for (int lab = 1; lab <= 5; ++lab) labs[lab].lab = lab;
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
    c.maxPoints = setup.points.points(c.lab, c.name, kDefaultCheckPoints);
    c.points = c.passed ? c.maxPoints : 0.;
    result.checks.push_back(std::move(c));
}

// Reads and compares one picture; every way a file can be wrong is a reason of its own.
FigureOutcome gradePicture(const GradeSetup& setup, const FigureReference& reference, const fs::path& file) {
    FigureOutcome f;
    f.id = reference.id;
    f.lab = reference.lab;
    f.maxPoints = setup.points.points(f.lab, figureItem(f.id), kDefaultFigurePoints);
    std::error_code error;
    if (!fs::exists(file, error)) {
        f.found = false;
        f.reason = "missing: there is no " + file.string();
        return f;
    }
    {
        std::ifstream in(file, std::ios::binary);
        std::array<char, 8> magic{};
        in.read(magic.data(), magic.size());
        static constexpr std::array<char, 8> kPng{'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n'};
        if (!in || magic != kPng) {
            f.reason = "not a PNG file: " + file.string() + (in ? " has another format" : " is empty or unreadable");
            return f;
        }
    }
    Image8 image;
    try {
        image = readImage(file);
    } catch (const std::exception& e) {
        f.reason = std::string("unreadable (truncated or damaged?): ") + e.what();
        return f;
    }
    f.studentImage = file;
    f.verdict = compareImage(reference, image);
    f.passed = f.verdict.passed;
    f.reason = f.verdict.reason;
    if (!f.passed && image.width == reference.image.width && image.height == reference.image.height) {
        const Diagnosis d = diagnose(setup.mistakes, f.id, image, reference.image);
        f.diagnosis = d.text();
    }
    f.points = f.passed ? f.maxPoints : 0.;
    return f;
}

// Every item of a lab at zero, because its code did not build.
void addUnbuiltLab(const GradeSetup& setup, GradeResult& result, int lab) {
    if (const auto it = setup.points.labs.find(lab); it != setup.points.labs.end())
        for (const auto& [item, points] : it->second)
            if (isCheckItem(item)) addCheck(setup, result, CheckOutcome{lab, item, false, "the code does not build (the compiler's message is at the top of the report)", 0., 0.});
    for (const FigureReference& reference : setup.references.figures) {
        if (reference.lab != lab) continue;
        FigureOutcome f;
        f.id = reference.id;
        f.lab = reference.lab;
        f.maxPoints = setup.points.points(f.lab, figureItem(f.id), kDefaultFigurePoints);
        f.reason = "the code does not build (the compiler's message is at the top of the report)";
        result.figures.push_back(std::move(f));
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

const std::vector<int>& labDependencies(int lab) {
    static const std::map<int, std::vector<int>> deps{{1, {}}, {2, {4}}, {3, {2}}, {4, {2, 3}}, {5, {2, 3}}};
    static const std::vector<int> none;
    const auto it = deps.find(lab);
    return it == deps.end() ? none : it->second;
}

GradeSetup loadGradeSetup(const fs::path& references, const fs::path& points, const fs::path& scenes,
                          const fs::path& scratch) {
    GradeSetup setup;
    setup.references = loadReferences(references);
    setup.mistakes = loadMistakes(references);
    setup.points = loadPointsTable(points);
    setup.scenes = scenes;
    setup.scratch = scratch;
    return setup;
}

GradeResult gradeCode(const GradeSetup& setup, const std::vector<AgentPlan>& agents, bool isolated,
                      const std::vector<int>& unbuilt, const std::string& buildMessage) {
    GradeResult result;
    if (!unbuilt.empty()) {
        std::string labs;
        for (int lab : unbuilt) labs += " " + std::to_string(lab);
        result.problems.push_back("lab" + labs + ": the code does not build, so those labs get 0:\n" + buildMessage);
    }
    std::map<int, const AgentPlan*> agentOfLab;
    for (const AgentPlan& plan : agents)
        for (int lab = 1; lab <= 5; ++lab)
            if (plan.lab == 0 || plan.lab == lab) agentOfLab[lab] = &plan;
    std::map<const AgentPlan*, Reported> reports;
    for (const AgentPlan& plan : agents) {
        reports[&plan] = runUntilDone(setup, plan);
        for (const std::string& p : reports[&plan].problems) result.problems.push_back(p);
    }
    for (int lab = 1; lab <= 5; ++lab) {
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
        if (const auto it = setup.points.labs.find(lab); it != setup.points.labs.end())
            for (const auto& [item, points] : it->second)
                if (isCheckItem(item) && !r.checks.count(item))
                    addCheck(setup, result, CheckOutcome{lab, item, false, "never ran: the code stopped before this check", 0., 0.});
        for (const FigureReference& reference : setup.references.figures) {
            if (reference.lab != lab) continue;
            const auto it = r.figures.find(reference.id);
            FigureOutcome f;
            const std::string status = it != r.figures.end() ? it->second.value("status", "") : "";
            if (status == "rendered") {
                f = gradePicture(setup, reference, setup.scratch / ("agent-" + (plan.lab ? "lab" + std::to_string(plan.lab) : std::string("all"))) / "figures" / (reference.id + ".png"));
            } else {
                f.id = reference.id;
                f.lab = lab;
                f.maxPoints = setup.points.points(lab, figureItem(f.id), kDefaultFigurePoints);
                f.reason = it == r.figures.end() ? "not rendered: the code stopped before this figure"
                           : status == "todo"    ? it->second.value("message", "")
                                                 : "rendering failed: " + it->second.value("message", "");
            }
            result.figures.push_back(std::move(f));
        }
    }
    scoreLabs(result);
    for (LabOutcome& lab : result.labs) {
        if (isolated) {
            lab.notes.push_back("graded on its own: the other labs came from the reference solutions");
            continue;
        }
        if (lab.points >= lab.maxPoints) continue;
        for (int dep : labDependencies(lab.lab)) {
            const LabOutcome& other = result.labs[std::size_t(dep - 1)];
            if (other.points >= other.maxPoints) continue;
            // Only when a failure of this lab can come from that one: a figure drawn with its code,
            // or a check whose message names it ("lab 4 not done yet").
            const std::string name = "lab " + std::to_string(dep);
            const bool figure = std::any_of(result.figures.begin(), result.figures.end(), [&](const FigureOutcome& f) {
                return f.lab == lab.lab && !f.passed && dep != 4;
            });
            const bool check = std::any_of(result.checks.begin(), result.checks.end(), [&](const CheckOutcome& c) {
                return c.lab == lab.lab && !c.passed && c.message.find(name + " ") != std::string::npos;
            });
            if (figure || check)
                lab.notes.push_back("lab " + std::to_string(lab.lab) + " uses lab " + std::to_string(dep) +
                                    ", which has failures: fix lab " + std::to_string(dep) + " first");
        }
    }
    return result;
}

GradeResult gradeImages(const GradeSetup& setup, const fs::path& folder) {
    GradeResult result;
    std::error_code error;
    if (!fs::is_directory(folder, error)) result.problems.push_back("no folder " + folder.string());
    for (const FigureReference& reference : setup.references.figures)
        result.figures.push_back(gradePicture(setup, reference, folder / (reference.id + ".png")));
    if (fs::is_directory(folder, error))
        for (const auto& entry : fs::directory_iterator(folder))
            if (entry.path().extension() == ".png" && !setup.references.find(entry.path().stem().string()))
                result.problems.push_back("ignored " + entry.path().filename().string() + ": no figure has this id");
    scoreLabs(result);
    return result;
}

GradeResult gradeBuildFailure(const GradeSetup& setup, const std::string& compilerMessage) {
    return gradeCode(setup, {}, false, {1, 2, 3, 4, 5}, compilerMessage);
}

} // namespace raylab::grader
