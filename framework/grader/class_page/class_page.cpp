#include "grader/class_page/class_page.h"

#include "src/atomic_file.h"
#include "src/markup.h"
#include "src/messages.h"
#include "src/svg_plot.h"
#include "src/text.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

namespace raylab::grader {

namespace fs = std::filesystem;

namespace {

constexpr int kHistogramBins = 10;

std::string html(const std::string& text) { return escapeMarkup(printableText(text)); }

std::string number(double v) { return formatNumber(v, 4); }

// A relative link to a file under OUT: the safe names' '%' written %25, so the browser finds the
// folder as it is named.
std::string link(const std::string& relative) {
    std::string href;
    for (char c : relative) href += c == '%' ? std::string("%25") : std::string(1, c);
    return escapeMarkup(href);
}

std::string reportLink(const ClassMember& m) {
    return "<a href=\"" + link("students/" + m.place.filename().string() + "/report/index.html") + "\">" + html(m.student) + "</a>";
}

std::string labName(int lab) { return tr("report.lab", {{"lab", std::to_string(lab)}}); }

// ---- the scores ---------------------------------------------------------------------------------

void writeHistograms(std::ostream& page, const ClassResults& results) {
    std::map<int, std::vector<double>> points;
    std::map<int, double> most;
    std::vector<double> totals;
    double mostTotal = 0.;
    for (const ClassMember& m : results.students) {
        for (const LabScore& l : m.outcome.labs) {
            points[l.lab].push_back(l.points);
            most[l.lab] = std::max(most[l.lab], l.maxPoints);
        }
        totals.push_back(m.outcome.points());
        mostTotal = std::max(mostTotal, m.outcome.maxPoints());
    }
    const std::string students = tr("class_page.students_axis"), scored = tr("class_page.points_axis");
    page << "<h2>" << tr("class_page.scores") << "</h2>\n<div class=\"plots\">\n";
    page << toSvg(histogramOf(tr("class_page.total"), scored, students, totals, 0., mostTotal, kHistogramBins));
    for (const auto& [lab, values] : points)
        page << toSvg(histogramOf(labName(lab), scored, students, values, 0., most[lab], kHistogramBins));
    page << "</div>\n";
}

// ---- pass rates ---------------------------------------------------------------------------------

struct ItemRate {
    bool figure = false;
    int lab = 0;
    std::string name;
    int passed = 0, graded = 0;
    double rate() const { return graded ? double(passed) / graded : 0.; }
};

std::vector<ItemRate> passRates(const ClassResults& results) {
    std::map<std::tuple<int, bool, std::string>, ItemRate> rates;
    for (const ClassMember& m : results.students)
        for (const ItemVerdict& i : m.outcome.items) {
            ItemRate& r = rates[{i.lab, i.figure, i.name}];
            r.figure = i.figure, r.lab = i.lab, r.name = i.name;
            ++r.graded;
            r.passed += i.passed ? 1 : 0;
        }
    std::vector<ItemRate> sorted;
    for (const auto& [key, rate] : rates) sorted.push_back(rate);
    std::stable_sort(sorted.begin(), sorted.end(), [](const ItemRate& a, const ItemRate& b) { return a.rate() < b.rate(); });
    return sorted;
}

void writePassRates(std::ostream& page, const ClassResults& results) {
    page << "<h2>" << tr("class_page.pass_rates") << "</h2>\n<table class=\"rates\"><tr><th>" << tr("report.html.lab")
         << "</th><th>" << tr("class_page.item") << "</th><th>" << tr("class_page.passed") << "</th><th></th></tr>\n";
    for (const ItemRate& r : passRates(results)) {
        const std::string item = r.figure ? tr("report.figure_item", {{"id", r.name}}) : titleInLanguage(r.name);
        const int percent = int(std::lround(100. * r.rate()));
        page << "<tr data-item=\"" << html(r.name) << "\" data-passed=\"" << r.passed << "\" data-graded=\"" << r.graded
             << "\"><td>" << labName(r.lab) << "</td><td>" << html(item) << "</td><td>" << r.passed << " / " << r.graded << " ("
             << tr("class_page.percent", {{"value", std::to_string(percent)}}) << ")</td><td><span class=\"bar\" style=\"width:" << percent << "px\"></span></td></tr>\n";
    }
    page << "</table>\n";
}

// ---- mistakes -----------------------------------------------------------------------------------

void writeMistakes(std::ostream& page, const ClassPageInput& input) {
    std::map<std::string, std::vector<const ClassMember*>> made; // mistake id -> students, each once
    for (const ClassMember& m : input.results.students) {
        std::set<std::string> own;
        for (const ItemVerdict& i : m.outcome.items) own.insert(i.mistakes.begin(), i.mistakes.end());
        for (const std::string& id : own) made[id].push_back(&m);
    }
    std::vector<std::pair<std::string, std::vector<const ClassMember*>>> sorted(made.begin(), made.end());
    std::stable_sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.second.size() > b.second.size(); });
    page << "<h2>" << tr("class_page.mistakes") << "</h2>\n";
    if (sorted.empty()) {
        page << "<p>" << tr("class_page.no_mistakes") << "</p>\n";
        return;
    }
    page << "<table><tr><th>" << tr("class_page.students") << "</th><th>" << tr("class_page.mistake") << "</th><th>"
         << tr("class_page.hint") << "</th><th>" << tr("class_page.who") << "</th></tr>\n";
    for (const auto& [id, students] : sorted) {
        const auto it = std::find_if(input.mistakes.begin(), input.mistakes.end(),
                                     [&mistake = id](const Mistake& m) { return m.id == mistake; }); // Clang 14: no binding captured
        std::string name = html(id), hint;
        if (it != input.mistakes.end()) {
            name = html(it->name()) + "<br><small>" + labName(it->lab) + ", " + html(it->function) + "</small>";
            hint = html(it->hint());
            if (!it->label.empty()) hint += " <small>(" + html(tr("class_page.handout_label", {{"label", it->label}})) + ")</small>";
        }
        std::string who;
        for (const ClassMember* m : students) who += (who.empty() ? "" : ", ") + reportLink(*m);
        page << "<tr id=\"mistake-" << html(id) << "\" data-mistake=\"" << html(id) << "\" data-students=\"" << students.size()
             << "\"><td>" << students.size() << "</td><td>" << name << "</td><td>" << hint << "</td><td>" << who << "</td></tr>\n";
    }
    page << "</table>\n";
}

// ---- builds that failed, runs that stopped --------------------------------------------------------

void writeTrouble(std::ostream& page, const ClassResults& results) {
    std::ostringstream rows;
    for (const ClassMember& m : results.students) {
        std::string unbuilt, stopped;
        for (const LabScore& l : m.outcome.labs)
            if (l.unbuilt) unbuilt += (unbuilt.empty() ? "" : ", ") + std::to_string(l.lab);
        for (const ItemVerdict& i : m.outcome.items)
            if (i.stopped) stopped += (stopped.empty() ? "" : ", ") + html(i.figure ? i.name : titleInLanguage(i.name));
        if (unbuilt.empty() && stopped.empty()) continue;
        std::string problems;
        for (const std::string& p : m.outcome.problems) problems += "<pre>" + html(p) + "</pre>";
        rows << "<tr data-student=\"" << html(m.student) << "\"><td>" << reportLink(m) << "</td><td>" << unbuilt << "</td><td>"
             << stopped << "</td><td>" << problems << "</td></tr>\n";
    }
    page << "<h2>" << tr("class_page.trouble") << "</h2>\n";
    if (rows.str().empty()) {
        page << "<p>" << tr("class_page.no_trouble") << "</p>\n";
        return;
    }
    page << "<table><tr><th>" << tr("class_page.student") << "</th><th>" << tr("class_page.unbuilt") << "</th><th>"
         << tr("class_page.stopped") << "</th><th>" << tr("class_page.problems") << "</th></tr>\n"
         << rows.str() << "</table>\n";
}

// ---- similar submissions ------------------------------------------------------------------------

constexpr const char* kRunColours[] = {"#ffe08a", "#a8e6a1", "#a8d0f0", "#f5b7b1", "#d7bde2", "#f9e79f"};

// One side of a pair: its lines numbered, those of a matched run coloured as the run, the stub's grey.
std::string codeColumn(const LabSimilarity& lab, std::size_t student, const SimilarPair& pair, bool first) {
    std::vector<int> runOfLine;
    std::istringstream lines(lab.texts[student]);
    std::string out = "<div class=\"side\"><h3>" + html(lab.students[student]) + "</h3><pre>";
    int number = 0;
    for (std::string line; std::getline(lines, line);) {
        ++number;
        int run = -1;
        for (std::size_t r = 0; r < pair.runs.size(); ++r) {
            const MatchedRun& m = pair.runs[r];
            if (first ? (number >= m.firstFrom && number <= m.firstTo) : (number >= m.secondFrom && number <= m.secondTo)) run = int(r);
        }
        const bool stub = std::size_t(number - 1) < lab.leftOut[student].size() && lab.leftOut[student][std::size_t(number - 1)];
        std::string style = stub ? " class=\"stub\"" : "";
        if (run >= 0 && !stub)
            style = " style=\"background:" + std::string(kRunColours[std::size_t(run) % std::size(kRunColours)]) + "\"";
        out += "<span" + style + ">" + std::to_string(number) + "  " + html(line) + "</span>\n";
    }
    return out + "</pre></div>";
}

std::string pairPageName(int lab, std::size_t rank) { return "similarity/lab" + std::to_string(lab) + "-" + std::to_string(rank + 1) + ".html"; }

void writePairPage(const LabSimilarity& lab, const SimilarPair& pair, const fs::path& file) {
    std::ostringstream page;
    const std::string title = tr("class_page.pair_title", {{"lab", std::to_string(lab.lab)}, {"first", lab.students[pair.first]},
                                                           {"second", lab.students[pair.second]}});
    page << "<!doctype html>\n<html lang=\"" << languageCode(language()) << "\"><head><meta charset=\"utf-8\"><title>" << html(title)
         << "</title>\n<style>body{font-family:sans-serif}.pair{display:flex;gap:1em}.side{flex:1;overflow:auto}"
            "pre{font-size:12px}.stub{color:#aaa}</style></head><body>\n<h1>"
         << html(title) << "</h1>\n<p>"
         << tr("class_page.pair_summary", {{"overlap", std::to_string(pair.overlap)}, {"median", number(lab.median)},
                                           {"runs", std::to_string(pair.runs.size())}})
         << "</p>\n<p>" << tr("class_page.not_a_verdict") << "</p>\n<div class=\"pair\">"
         << codeColumn(lab, pair.first, pair, true) << codeColumn(lab, pair.second, pair, false) << "</div>\n</body></html>\n";
    writeFileAtomically(file, page.str());
}

void writeSimilarity(std::ostream& page, const ClassPageInput& input, const fs::path& out) {
    page << "<h2>" << tr("class_page.similarity") << "</h2>\n<p>" << tr("class_page.not_a_verdict") << "</p>\n";
    if (!input.similarity.note.empty()) page << "<p class=\"note\">" << html(input.similarity.note) << "</p>\n";
    for (const LabSimilarity& lab : input.similarity.labs) {
        page << "<h3>" << labName(lab.lab) << "</h3>\n<p>"
             << tr("class_page.usual_overlap",
                   {{"students", std::to_string(lab.students.size())}, {"median", number(lab.median)},
                    {"pairs", std::to_string(lab.comparedPairs)},
                    {"fence", tr(lab.fence < 100. ? "class_page.fence" : "class_page.no_fence", {{"fence", number(lab.fence)}})}})
             << "</p>\n";
        if (lab.pairs.empty()) continue;
        page << "<table class=\"similar\" data-lab=\"" << lab.lab << "\"><tr><th>" << tr("class_page.student") << "</th><th>"
             << tr("class_page.student") << "</th><th>" << tr("class_page.overlap") << "</th><th></th></tr>\n";
        for (std::size_t k = 0; k < lab.pairs.size(); ++k) {
            const SimilarPair& pair = lab.pairs[k];
            writePairPage(lab, pair, out / pairPageName(lab.lab, k));
            page << "<tr data-first=\"" << html(lab.students[pair.first]) << "\" data-second=\"" << html(lab.students[pair.second])
                 << "\" data-overlap=\"" << pair.overlap << "\"" << (pair.unusual ? " class=\"unusual\"" : "") << "><td>"
                 << html(lab.students[pair.first]) << "</td><td>" << html(lab.students[pair.second]) << "</td><td>" << tr("class_page.percent", {{"value", std::to_string(pair.overlap)}}) << (pair.unusual ? " — " + tr("class_page.unusual") : "") << "</td><td><a href=\""
                 << link(pairPageName(lab.lab, k)) << "\">" << tr("class_page.side_by_side") << "</a></td></tr>\n";
        }
        page << "</table>\n";
    }
}

// ---- the gradebook and every student ------------------------------------------------------------

void writeGradebookNotes(std::ostream& page, const GradebookFiles& gradebook) {
    page << "<h2>" << tr("class_page.gradebook") << "</h2>\n<p><a href=\"gradebook-moodle.csv\">gradebook-moodle.csv</a> "
         << tr("class_page.moodle") << ", <a href=\"gradebook-canvas.csv\">gradebook-canvas.csv</a> " << tr("class_page.canvas")
         << ", <a href=\"grades.csv\">grades.csv</a></p>\n";
    const auto list = [&](const std::vector<std::string>& names, const char* id) {
        if (names.empty()) return;
        std::string joined;
        for (const std::string& n : names) joined += (joined.empty() ? "" : ", ") + html(n);
        page << "<p class=\"note\" id=\"" << id << "\">" << tr(std::string("class_page.") + id, {{"count", std::to_string(names.size())}})
             << " " << joined << "</p>\n";
    };
    list(gradebook.unknown, "roster_unknown");
    list(gradebook.missing, "roster_missing");
    list(gradebook.unreadable, "gradebook_unreadable");
}

void writeStudents(std::ostream& page, const ClassResults& results) {
    std::set<int> labs;
    for (const ClassMember& m : results.students)
        for (const LabScore& l : m.outcome.labs) labs.insert(l.lab);
    page << "<h2>" << tr("class_page.every_student") << "</h2>\n<table><tr><th>" << tr("class_page.student") << "</th>";
    for (int lab : labs) page << "<th>" << labName(lab) << "</th>";
    page << "<th>" << tr("class_page.total") << "</th></tr>\n";
    for (const ClassMember& m : results.students) {
        page << "<tr><td>" << reportLink(m) << "</td>";
        for (int lab : labs) {
            std::string cell;
            for (const LabScore& l : m.outcome.labs)
                if (l.lab == lab) cell = number(l.points) + " / " + number(l.maxPoints);
            page << "<td>" << cell << "</td>";
        }
        page << "<td>" << number(m.outcome.points()) << " / " << number(m.outcome.maxPoints()) << "</td></tr>\n";
    }
    page << "</table>\n";
    for (const std::string& p : results.problems) page << "<p class=\"note\">" << html(p) << "</p>\n";
}

} // namespace

void writeClassPage(const ClassPageInput& input, const fs::path& out) {
    fs::create_directories(out / "similarity");
    std::ostringstream page;
    const std::string title = tr("class_page.title", {{"students", std::to_string(input.results.students.size())}});
    page << "<!doctype html>\n<html lang=\"" << languageCode(language()) << "\"><head><meta charset=\"utf-8\"><title>" << html(title)
         << "</title>\n<style>body{font-family:sans-serif;max-width:1400px;margin:auto}td,th{padding:3px 8px;text-align:left;"
            "vertical-align:top}.bar{display:inline-block;height:10px;background:#1f77b4}.plots{display:flex;flex-wrap:wrap;gap:8px}"
            ".unusual{background:#fde2e2}.note{color:#a60}pre{margin:0;white-space:pre-wrap}</style></head><body>\n<h1>"
         << html(title) << "</h1>\n";
    writeHistograms(page, input.results);
    writePassRates(page, input.results);
    writeMistakes(page, input);
    writeTrouble(page, input.results);
    writeSimilarity(page, input, out);
    writeGradebookNotes(page, input.gradebook);
    writeStudents(page, input.results);
    page << "</body></html>\n";
    writeFileAtomically(out / "index.html", page.str());
}

} // namespace raylab::grader
