#include "grader/course/grade_reports.h"

#include "grader/course/glossary_links.h"

#include "grader/judge/checks/checks.h"

#include "src/atomic_file.h"
#include "src/markup.h"
#include "src/messages.h"
#include "src/text.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace raylab::grader {

namespace fs = std::filesystem;

namespace {

std::string number(double v) { return formatNumber(v, 4); }

// "PASS" or "FAIL", in the reader's language.
std::string verdict(bool passed) { return tr(passed ? "report.pass" : "report.fail"); }

// The heat map: black where the pixel agrees, red to yellow as the error grows to `full`.
Image8 heatMap(const ImageVerdict& v, float full) {
    Image8 image{v.width, v.height, {}};
    image.rgb.reserve(v.error.size() * 3);
    for (float e : v.error) {
        const float x = std::min(1.f, e / full);
        image.rgb.push_back(std::uint8_t(e <= 1.f && full > 6.f ? 40.f * e : 80.f + 175.f * x));
        image.rgb.push_back(std::uint8_t(x > 0.5f ? 255.f * (x - 0.5f) * 2.f : 0.f));
        image.rgb.push_back(0);
    }
    return image;
}

std::string itemOutput(const FigureOutcome& f) {
    std::string text = f.reason;
    if (!f.diagnosis.empty()) text += "\n" + f.diagnosis;
    for (const auto& [name, value] : f.verdict.metrics)
        text += "\n  " + tr("report.metric", {{"name", name}, {"value", number(value)}});
    return text;
}

// Text from outside (a compiler's, an agent's message) in markup: well-formed UTF-8 without the
// characters XML 1.0 forbids (an ESC from an exception message), then escaped.
std::string markupText(const std::string& text) { return escapeMarkup(printableText(text)); }

} // namespace

void writeHtmlReport(const GradeResult& result, const ReferenceSet& references, const fs::path& folder) {
    const fs::path images = folder / "images";
    fs::create_directories(images);
    std::ostringstream out;
    out << "<!doctype html>\n<html lang=\"" << languageCode(language()) << "\"><head><meta charset=\"utf-8\"><title>" << markupText(result.title)
        << "</title>\n<style>body{font-family:sans-serif;max-width:1400px;margin:auto}"
           "img{width:300px;image-rendering:pixelated;border:1px solid #ccc}.pass{color:#080}.fail{color:#b00}"
           "td,th{padding:4px 8px;vertical-align:top;text-align:left}pre{white-space:pre-wrap;margin:0}</style>"
           "</head><body>\n<h1>"
        << markupText(result.title) << "</h1>\n<p>"
        << tr("report.html.score", {{"score", "<b>" + number(result.score()) + " / " + number(result.maxScore()) + "</b>"}})
        << "</p>\n<table><tr><th>" << tr("report.html.lab") << "</th><th>" << tr("report.html.points") << "</th><th>"
        << tr("report.html.notes") << "</th></tr>\n";
    for (const LabOutcome& lab : result.labs) {
        std::string notes;
        for (const std::string& n : lab.notes) notes += markupText(n) + "<br>";
        out << "<tr><td>" << tr("report.lab", {{"lab", std::to_string(lab.lab)}}) << "</td><td>" << number(lab.points) << " / " << number(lab.maxPoints)
            << "</td><td>" << notes << "</td></tr>\n";
    }
    out << "</table>\n";
    for (const std::string& p : result.problems) out << "<p class=\"fail\"><pre>" << markupText(p) << "</pre></p>\n";
    out << "<h2>" << tr("report.html.figures") << "</h2>\n<table><tr><th>" << tr("report.html.figure") << "</th><th>"
        << tr("report.html.reference") << "</th><th>" << tr("report.html.yours") << "</th><th>"
        << tr("report.html.difference") << "</th><th>" << tr("report.html.verdict") << "</th></tr>\n";
    for (const FigureOutcome& f : result.figures) {
        const FigureReference* reference = references.find(f.id);
        out << "<tr><td>" << markupText(f.id) << "<br>" << tr("report.lab", {{"lab", std::to_string(f.lab)}}) << "<br>" << number(f.points) << " / "
            << number(f.maxPoints) << "</td><td>";
        if (reference) {
            writePng(images / (f.id + ".reference.png"), reference->image);
            out << "<img src=\"images/" << markupText(f.id) << ".reference.png\">";
        }
        out << "</td><td>";
        if (!f.studentImage.empty()) {
            copyFileAtomically(f.studentImage, images / (f.id + ".student.png"));
            out << "<img src=\"images/" << markupText(f.id) << ".student.png\">";
        }
        out << "</td><td>";
        if (!f.verdict.error.empty()) {
            const bool statistical = reference && reference->stats;
            writePng(images / (f.id + ".diff.png"), heatMap(f.verdict, statistical ? 6.f : 64.f));
            out << "<img src=\"images/" << markupText(f.id) << ".diff.png\"><br><small>"
                << markupText(tr(statistical ? "report.html.scale_z" : "report.html.scale_lsb")) << "</small>";
        }
        out << "</td><td><b class=\"" << (f.passed ? "pass" : "fail") << "\">" << verdict(f.passed) << "</b><pre>"
            << markupText(itemOutput(f)) << "</pre></td></tr>\n";
    }
    out << "</table>\n<h2>" << tr("report.html.checks") << "</h2>\n<table><tr><th>" << tr("report.html.lab")
        << "</th><th>" << tr("report.html.check") << "</th><th>" << tr("report.html.points") << "</th><th>"
        << tr("report.html.verdict") << "</th></tr>\n";
    for (const CheckOutcome& c : result.checks)
        out << "<tr><td>" << tr("report.lab", {{"lab", std::to_string(c.lab)}}) << "</td><td>"
            << markupText(titleInLanguage(c.name)) << "</td><td>" << number(c.points) << " / " << number(c.maxPoints)
            << "</td><td><b class=\"" << (c.passed ? "pass" : "fail") << "\">" << verdict(c.passed) << "</b><pre>"
            << markupText(c.message) << "</pre></td></tr>\n";
    out << "</table>\n</body></html>\n";
    writeFileAtomically(folder / "index.html", out.str());
}

// Gradescope's autograder format, its documented fields only: every item with its points, always
// visible, its message (expected, got, hint) or its verdict and diagnosis as output; no leaderboard.
void writeGradescopeJson(const GradeResult& result, const fs::path& file) {
    nlohmann::json tests = nlohmann::json::array();
    auto test = [&](const std::string& name, double points, double maxPoints, bool passed, const std::string& output) {
        tests.push_back({{"name", name},
                         {"score", points},
                         {"max_score", maxPoints},
                         {"status", passed ? "passed" : "failed"},
                         {"output", printableText(output)},
                         {"visibility", "visible"}});
    };
    // Named in the reader's language: "lab3: intersect: ...", "TP 3 : intersect : ...".
    const auto itemName = [](int lab, const std::string& name) {
        return tr("report.item", {{"lab", tr("report.lab_short", {{"lab", std::to_string(lab)}})}, {"name", name}});
    };
    for (const CheckOutcome& c : result.checks)
        test(itemName(c.lab, printableText(titleInLanguage(c.name))), c.points, c.maxPoints, c.passed, c.message);
    for (const FigureOutcome& f : result.figures)
        test(itemName(f.lab, tr("report.figure_item", {{"id", f.id}})), f.points, f.maxPoints, f.passed, itemOutput(f));
    std::string output = tr("report.total", {{"score", number(result.score())}, {"max", number(result.maxScore())}}) + "\n";
    for (const LabOutcome& lab : result.labs) {
        output += tr("report.lab_points", {{"lab", std::to_string(lab.lab)}, {"points", number(lab.points)},
                                           {"max", number(lab.maxPoints)}}) + "\n";
        for (const std::string& n : lab.notes) output += "  " + n + "\n";
    }
    for (const std::string& p : result.problems) output += p + "\n";
    const nlohmann::json root{{"score", result.score()},
                              {"output", printableText(output)},
                              {"visibility", "visible"},
                              {"stdout_visibility", "visible"},
                              {"extra_data", {{"max_score", result.maxScore()}}},
                              {"tests", tests}};
    writeFileAtomically(file, root.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

void writeJUnitXml(const GradeResult& result, const fs::path& file) {
    std::ostringstream out;
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"" << markupText(result.title) << "\">\n";
    for (const LabOutcome& outcome : result.labs) {
        const int lab = outcome.lab;
        std::ostringstream cases;
        int tests = 0, failures = 0;
        auto item = [&](const std::string& name, bool passed, const std::string& message) {
            ++tests;
            cases << "  <testcase classname=\"lab" << lab << "\" name=\"" << markupText(name) << "\">";
            if (!passed) {
                ++failures;
                cases << "<failure message=\"" << markupText(message.substr(0, message.find('\n'))) << "\">"
                      << markupText(message) << "</failure>";
            }
            cases << "</testcase>\n";
        };
        for (const CheckOutcome& c : result.checks)
            if (c.lab == lab) item(titleInLanguage(c.name), c.passed, c.message);
        for (const FigureOutcome& f : result.figures)
            if (f.lab == lab) item("figure " + f.id, f.passed, itemOutput(f));
        if (tests == 0) continue;
        out << " <testsuite name=\"lab" << lab << "\" tests=\"" << tests << "\" failures=\"" << failures << "\">\n"
            << cases.str() << " </testsuite>\n";
    }
    out << "</testsuites>\n";
    writeFileAtomically(file, out.str());
}

void writeReports(const GradeResult& result, const ReferenceSet& references, const fs::path& folder) {
    fs::create_directories(folder);
    writeHtmlReport(result, references, folder);
    writeGradescopeJson(result, folder / "results.json");
    writeJUnitXml(result, folder / "junit.xml");
}

std::string terminalSummary(const GradeResult& result) {
    std::ostringstream out;
    for (const LabOutcome& l : result.labs) {
        const int lab = l.lab;
        bool any = false;
        for (const CheckOutcome& c : result.checks)
            if (c.lab == lab) {
                any = true;
                out << "  " << verdict(c.passed) << "  " << tr("report.lab_short", {{"lab", std::to_string(lab)}}) << "  "
                    << titleInLanguage(c.name) << "\n";
                if (!c.passed) {
                    std::istringstream lines(c.message);
                    for (std::string line; std::getline(lines, line);) out << "        " << line << "\n";
                }
            }
        for (const FigureOutcome& f : result.figures)
            if (f.lab == lab) {
                any = true;
                out << "  " << verdict(f.passed) << "  " << tr("report.lab_short", {{"lab", std::to_string(lab)}}) << "  "
                    << tr("report.figure_line", {{"id", f.id}, {"reason", f.reason}}) << "\n";
                if (!f.diagnosis.empty()) out << "        " << f.diagnosis << "\n";
            }
        if (!any) continue;
        out << "  "
            << tr("report.lab_points",
                  {{"lab", std::to_string(lab)}, {"points", number(l.points)}, {"max", number(l.maxPoints)}})
            << "\n";
        for (const std::string& n : l.notes) out << "        " << n << "\n";
    }
    for (const std::string& p : result.problems) out << "  " << tr("report.problem", {{"problem", p}}) << "\n";
    out << "  " << tr("report.total", {{"score", number(result.score())}, {"max", number(result.maxScore())}}) << "\n";
    return printableText(withGlossaryLinks(out.str())); // no escape sequence of a message reaches the terminal
}

} // namespace raylab::grader
