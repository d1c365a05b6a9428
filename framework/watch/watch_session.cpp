#include "watch/watch_session.h"

#include "watch/page_document.h"

#include "grader/course/grade_reports.h"
#include "grader/course/run_scratch.h"
#include "grader/course/submission.h"
#include "grader/judge/grade.h"
#include "grader/sandbox/process.h"
#include "src/messages.h"
#include "src/text.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <memory>
#include <cstdio>

namespace raylab::watch {

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A picture of the report's images/ folder, as the page asks for it; empty when it was not written.
std::string picture(const fs::path& out, const std::string& id, const std::string& kind) {
    const fs::path relative = fs::path("report") / "images" / (id + "." + kind + ".png");
    std::error_code error;
    return fs::is_regular_file(out / relative, error) ? relative.generic_string() : std::string();
}

Json gradedJson(const grader::GradeResult& result, const grader::ReferenceSet& references, const fs::path& out) {
    Json figures = Json::array(), checks = Json::array(), labs = Json::array();
    for (const grader::FigureOutcome& f : result.figures) {
        const grader::FigureReference* reference = references.find(f.id);
        const bool statistical = reference != nullptr && reference->stats.has_value();
        figures.push_back({{"id", f.id},
                           {"passed", f.passed},
                           {"reason", printableText(f.reason)},
                           {"diagnosis", printableText(f.diagnosis)},
                           {"width", reference != nullptr ? reference->image.width : 0},
                           {"height", reference != nullptr ? reference->image.height : 0},
                           {"student", f.studentImage.empty() ? std::string() : picture(out, f.id, "student")},
                           {"reference", picture(out, f.id, "reference")},
                           {"difference", picture(out, f.id, "diff")},
                           {"scale", tr(statistical ? "report.html.scale_z" : "report.html.scale_lsb")}});
    }
    for (const grader::CheckOutcome& c : result.checks)
        checks.push_back({{"name", printableText(titleInLanguage(c.name))},
                          {"passed", c.passed},
                          {"message", printableText(c.message)},
                          {"points", c.points},
                          {"max", c.maxPoints}});
    for (const grader::LabOutcome& l : result.labs) {
        Json notes = Json::array();
        for (const std::string& n : l.notes) notes.push_back(printableText(n));
        labs.push_back({{"lab", l.lab}, {"points", l.points}, {"max", l.maxPoints}, {"notes", notes}});
    }
    Json problems = Json::array();
    for (const std::string& p : result.problems) problems.push_back(printableText(p));
    return {{"figures", figures}, {"checks", checks}, {"labs", labs}, {"problems", problems}};
}

// A grade that is a problem alone: what kept the lab from being graded.
std::string problemOnly(const std::string& problem) { return jsonText(Json{{"problems", Json::array({printableText(problem)})}}); }

} // namespace

WatchSession::WatchSession(WatchSettings settings, PageState& page, std::mutex& agents)
    : m_settings(std::move(settings)), m_page(page), m_agents(agents) {}

std::string WatchSession::buildAgent() {
    // The lab's own agent (the other labs from the reference where solutions/ is, else the labs it uses
    // from the student's code and the others' stubs); the whole set the first time, when none is built
    // yet. One build at a time in the folder: `raylab grade` beside the page waits, or this waits for it.
    const std::string target = grader::labAgentTarget(m_settings.binDir, m_settings.lab);
    const std::unique_ptr<FileLock> building = grader::lockBuildFolder(m_settings.buildDir);
    grader::ProcessOptions options;
    options.keepOutput = 64 * 1024;
    const grader::ProcessResult built = grader::runProcess(
        {m_settings.cmake, "--build", m_settings.buildDir.string(), "--config", m_settings.buildType, "--target", target}, options);
    if (built.succeeded()) return "";
    const std::string output = built.kept.head + built.kept.tail + built.error;
    return output.empty() ? std::string("cmake --build: ") + tr("sandbox.exited") : output;
}

void WatchSession::refresh(const std::vector<fs::path>& changed) {
    publish("building", changed);
    const std::lock_guard lock(m_agents);
    auto start = std::chrono::steady_clock::now();
    try {
        m_buildOutput = buildAgent();
    } catch (const std::exception& e) { // cmake could not be started: a failed build, never the end of the watch
        m_buildOutput = e.what();
        if (m_buildOutput.empty()) m_buildOutput = "cmake --build";
    }
    m_buildSeconds = secondsSince(start);
    if (!m_buildOutput.empty()) {
        publish("build_failed", changed);
        return;
    }
    publish("grading", changed);
    start = std::chrono::steady_clock::now();
    try {
        const grader::RunScratch scratch("watch"); // the agents' folder, removed at its end
        grader::GradeSetup setup =
            grader::loadGradeSetup(m_settings.references, m_settings.labs, m_settings.scenes, scratch.path());
        setup.threads = m_settings.threads;
        bool isolated = false;
        std::vector<grader::AgentPlan> agents = grader::findAgents(m_settings.binDir, {m_settings.lab}, isolated);
        std::erase_if(agents, [&](const grader::AgentPlan& a) { return a.lab != 0 && a.lab != m_settings.lab; });
        for (grader::AgentPlan& a : agents) a.lab = m_settings.lab;
        grader::GradeResult result = grader::gradeCode(setup, agents, isolated);
        result.title = "raylab watch " + std::to_string(m_settings.lab);
        grader::writeReports(result, setup.references, m_settings.out / "report");
        m_graded = jsonText(gradedJson(result, setup.references, m_settings.out));
    } catch (const std::exception& e) {
        m_graded = problemOnly(e.what());
    }
    m_gradeSeconds = secondsSince(start);
    publish("ready", changed);
}

void WatchSession::showProblem(const std::string& problem) {
    m_graded = problemOnly(problem);
    publish("ready", {});
}

void WatchSession::publish(const std::string& phase, const std::vector<fs::path>& changed) {
    PageFacts facts{m_settings.lab, phase, {}, m_buildOutput, m_settings.sourceDir, m_buildSeconds, m_gradeSeconds};
    for (const fs::path& file : changed) facts.changed.push_back(fs::relative(file, m_settings.sourceDir).generic_string());
    m_page.publish(pageDocument(m_graded, facts));
}

} // namespace raylab::watch
