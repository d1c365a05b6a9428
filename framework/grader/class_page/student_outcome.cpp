#include "grader/class_page/student_outcome.h"

#include "grader/course/class_run.h"
#include "src/atomic_file.h"
#include "src/text.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <stdexcept>

namespace raylab::grader {

namespace fs = std::filesystem;

double StudentOutcome::points() const {
    double sum = 0.;
    for (const LabScore& lab : labs) sum += lab.points;
    return sum;
}

double StudentOutcome::maxPoints() const {
    double sum = 0.;
    for (const LabScore& lab : labs) sum += lab.maxPoints;
    return sum;
}

StudentOutcome outcomeOf(const GradeResult& result) {
    StudentOutcome outcome;
    for (const LabOutcome& lab : result.labs) outcome.labs.push_back({lab.lab, lab.points, lab.maxPoints, lab.unbuilt});
    for (const CheckOutcome& c : result.checks) outcome.items.push_back({false, c.lab, c.name, c.passed, c.stopped, {}});
    for (const FigureOutcome& f : result.figures)
        outcome.items.push_back({true, f.lab, f.id, f.passed, f.stopped, f.mistakes});
    for (const std::string& p : result.problems) outcome.problems.push_back(problemSummary(printableText(p)));
    return outcome;
}

void writeStudentOutcome(const StudentOutcome& outcome, const fs::path& file) {
    nlohmann::json labs = nlohmann::json::array(), items = nlohmann::json::array();
    for (const LabScore& l : outcome.labs)
        labs.push_back({{"lab", l.lab}, {"points", l.points}, {"max_points", l.maxPoints}, {"unbuilt", l.unbuilt}});
    for (const ItemVerdict& i : outcome.items)
        items.push_back({{"kind", i.figure ? "figure" : "check"}, {"lab", i.lab}, {"name", i.name}, {"passed", i.passed},
                         {"stopped", i.stopped}, {"mistakes", i.mistakes}});
    const nlohmann::json root{{"labs", labs}, {"items", items}, {"problems", outcome.problems}};
    writeFileAtomically(file, root.dump(1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

StudentOutcome readStudentOutcome(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + printablePath(file));
    try {
        const nlohmann::json root = nlohmann::json::parse(in);
        StudentOutcome outcome;
        for (const nlohmann::json& l : root.at("labs"))
            outcome.labs.push_back({l.at("lab").get<int>(), l.at("points").get<double>(), l.at("max_points").get<double>(),
                                    l.at("unbuilt").get<bool>()});
        for (const nlohmann::json& i : root.at("items"))
            outcome.items.push_back({i.at("kind").get<std::string>() == "figure", i.at("lab").get<int>(),
                                     i.at("name").get<std::string>(), i.at("passed").get<bool>(), i.at("stopped").get<bool>(),
                                     i.at("mistakes").get<std::vector<std::string>>()});
        outcome.problems = root.at("problems").get<std::vector<std::string>>();
        return outcome;
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(printablePath(file) + ": not a student's outcome (" + e.what() + ")");
    }
}

} // namespace raylab::grader
