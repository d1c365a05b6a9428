#include "report/report_pages.h"

#include "report/difference_map.h"
#include "report/templates.h"

#include "raylab/markup.h"

#include <cmark.h>

#include <cstdlib>
#include <map>
#include <memory>

namespace raylab::report {

namespace {

using grader::CheckOutcome;
using grader::FigureOutcome;
using grader::LabOutcome;

// Text the student typed (report.toml), as Markdown that shows it as typed.
std::string markdownText(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (std::string("\\`*_{}[]<>()#+-.!|").find(c) != std::string::npos) out += '\\';
        out += c;
    }
    return out;
}

// "**Name**: " ("**Nom** : " in French): the colon outside, where CommonMark lets the bold close.
std::string bold(const std::string& label, const Words& w) { return "**" + label + "**" + w.colon; }

// The points of the function checks and of the figures, of one lab (0: every lab).
std::string pointsDetail(const grader::GradeResult& grade, int lab, const Words& w) {
    double checks = 0., checksMax = 0., figures = 0., figuresMax = 0.;
    for (const CheckOutcome& k : grade.checks)
        if (lab == 0 || k.lab == lab) {
            checks += k.points;
            checksMax += k.maxPoints;
        }
    for (const FigureOutcome& f : grade.figures)
        if (lab == 0 || f.lab == lab) {
            figures += f.points;
            figuresMax += f.maxPoints;
        }
    return fill(w.totalDetail, {number(checks, -1, w), number(checksMax, -1, w), number(figures, -1, w), number(figuresMax, -1, w)});
}

Segment titleSegment(const KitContent& c) {
    const Words& w = c.words;
    const TitleBlock& t = c.title;
    std::string text = std::string("# ") + w.title + "\n\n";
    text += "- " + bold(w.name, w) + markdownText(t.name) + "\n";
    text += "- " + bold(w.group, w) + markdownText(t.group) + "\n";
    text += "- " + bold(w.course, w) + markdownText(t.course) + "\n";
    text += "- " + bold(w.date, w) + markdownText(t.date) + "\n";
    text += "- " + bold(w.total, w) + "**" + number(c.grade.score(), -1, w) + " / " + number(c.grade.maxScore(), -1, w) +
            "** (" + pointsDetail(c.grade, 0, w) + ")\n\n";
    text += std::string(w.intro) + "\n\n[" + w.fullReport + "](grade/index.html)\n";
    return {Segment::Kind::Generated, "title", text};
}

// The one-line reading of a difference map, with its scale.
std::string differenceReading(const KitFigure& f, const Words& w) {
    std::string line = fill(w.scaleReading, {"![scale](diff/scale.png)", std::to_string(kScaleFullLsb)});
    if (f.statistical) {
        line += ' ';
        line += fill(w.statisticalReading, {number(f.outlierZ, -1, w)});
    }
    return line + "\n\n";
}

std::string figureMarkdown(const KitFigure& f, const KitContent& c) {
    const Words& w = c.words;
    const grader::LabFigure* handout = c.labs.figure(f.id);
    std::string text = std::string("### ") + w.figure + " " + (handout ? handout->handout : "-") + " (" + f.id + ")\n\n";
    if (handout) text += handout->caption(w.lang) + "\n\n";
    if (!f.rendered) text += "**" + f.message + "**\n\n";
    text += std::string(w.picturesRow) + "\n\n";
    if (f.rendered) text += "![" + f.id + "](figures/" + f.id + ".png) ";
    if (f.hasReference) text += "![" + f.id + " reference](grade/images/" + f.id + ".reference.png) ";
    if (f.hasDifference) text += "![" + f.id + " difference](diff/" + f.id + ".png)";
    text += "\n\n";
    text += f.hasDifference ? differenceReading(f, w) : std::string("*") + w.noDifference + "*\n\n";
    if (f.rendered) text += std::string(w.renderTime) + w.colon + seconds(f.stats.seconds, w) + "\n\n";
    return text;
}

std::string checkLine(const CheckOutcome& k, const Words& w) {
    std::string line = std::string(k.passed ? "PASS" : "FAIL") + "  lab" + std::to_string(k.lab) + "  check " + k.name +
                       " (" + number(k.points, -1, w) + " / " + number(k.maxPoints, -1, w) + ")\n";
    if (!k.passed && !k.message.empty()) line += "        " + k.message + "\n";
    return line;
}

// The grader's line for a figure, as `raylab grade` prints it.
std::string figureLine(const FigureOutcome& f) {
    std::string line = std::string(f.passed ? "PASS" : "FAIL") + "  lab" + std::to_string(f.lab) + "  figure " + f.id +
                       ": " + f.reason + "\n";
    if (!f.diagnosis.empty()) line += "        " + f.diagnosis + "\n";
    return line;
}

std::string gradeMarkdown(const LabOutcome& lab, const KitContent& c) {
    const Words& w = c.words;
    std::string lines;
    for (const CheckOutcome& k : c.grade.checks)
        if (k.lab == lab.lab) lines += checkLine(k, w);
    for (const FigureOutcome& f : c.grade.figures)
        if (f.lab == lab.lab) lines += figureLine(f);
    lines += "lab " + std::to_string(lab.lab) + ": " + number(lab.points, -1, w) + " / " + number(lab.maxPoints, -1, w) +
             " (" + pointsDetail(c.grade, lab.lab, w) + ")\n";
    for (const std::string& note : lab.notes) lines += "note: " + note + "\n";
    return std::string("### ") + w.grade + "\n\n```text\n" + lines + "```\n\n";
}

const KitFigure* findFigure(const KitContent& c, const std::string& id) {
    for (const KitFigure& f : c.figures)
        if (f.id == id) return &f;
    return nullptr;
}

std::string costLine(const KitFigure& f, const char* label, const Words& w) {
    const double pixels = double(f.width) * double(f.height);
    const double samples = pixels > 0 ? double(f.stats.primaryRays) / pixels : 0.;
    return "- " + fill(w.cost, {label, number(samples, -1, w), std::to_string(f.stats.primaryRays), seconds(f.stats.seconds, w)}) + "\n";
}

std::string comparisonMarkdown(const KitContent& c) {
    const Words& w = c.words;
    const CloseUp& z = *c.closeUp;
    std::string text = std::string("### ") + w.comparison + "\n\n" + w.comparisonIntro + "\n\n";
    std::string pictures, closeUps, costs;
    for (const auto& [id, label] : {std::pair{kAliasedFigure, w.aliased}, std::pair{kAntialiasedFigure, w.antialiased}}) {
        const KitFigure* f = findFigure(c, id);
        if (f == nullptr || !f->rendered) {
            pictures += std::string("**") + (f ? f->message : std::string("no figure ") + id) + "** ";
            continue;
        }
        pictures += "![" + std::string(label) + "](figures/" + id + ".png) ";
        closeUps += "![" + std::string(id) + " close-up](zoom/" + id + ".png) ";
        costs += costLine(*f, label, w);
    }
    text += pictures + "\n\n" + costs + "\n" + closeUps + "\n\n";
    const KitFigure* aliased = findFigure(c, kAliasedFigure);
    text += fill(w.closeUp, {std::to_string(z.x), std::to_string(z.x + z.width - 1), std::to_string(z.y),
                             std::to_string(z.y + z.height - 1), std::to_string(aliased ? aliased->width : 0),
                             std::to_string(aliased ? aliased->height : 0), std::to_string(z.zoom)}) +
            "\n";
    return text;
}

bool drawsComparison(const KitContent& c, int lab) {
    const grader::LabDescription* owner = c.labs.labOfFigure(kAntialiasedFigure);
    return c.closeUp && owner != nullptr && owner->number == lab;
}

void appendLab(std::vector<Segment>& document, const LabOutcome& lab, const KitContent& c) {
    const Words& w = c.words;
    const grader::LabDescription* description = c.labs.lab(lab.lab);
    std::string text = std::string("## ") + w.lab + " " + std::to_string(lab.lab) +
                       (description ? w.colon + description->title(w.lang) : "") + "\n\n";
    for (const KitFigure& f : c.figures)
        if (f.lab == lab.lab) text += figureMarkdown(f, c);
    if (drawsComparison(c, lab.lab)) text += comparisonMarkdown(c);
    text += gradeMarkdown(lab, c);
    text += std::string("### ") + w.yourText + " (" + w.lab + " " + std::to_string(lab.lab) + ")\n";
    const std::string key = "lab" + std::to_string(lab.lab);
    document.push_back({Segment::Kind::Generated, key, text});
    document.push_back({Segment::Kind::Student, key, std::string("*") + w.yourTextHint + "*\n"});
}

// Markdown to HTML by cmark, safe: raw HTML and javascript: links are left out.
std::string markdownToHtml(const std::string& markdown) {
    const std::unique_ptr<char, decltype(&std::free)> html(
        cmark_markdown_to_html(markdown.c_str(), markdown.size(), CMARK_OPT_DEFAULT | CMARK_OPT_SMART), &std::free);
    return html ? std::string(html.get()) : std::string();
}

// `text` with every {{name}} replaced by its value, in one pass: a value is never searched again.
std::string substitute(const std::string& text, const std::map<std::string, std::string>& values) {
    std::string out;
    std::size_t at = 0;
    for (std::size_t open = text.find("{{"); open != std::string::npos; open = text.find("{{", at)) {
        const std::size_t close = text.find("}}", open);
        if (close == std::string::npos) break;
        const auto value = values.find(text.substr(open + 2, close - open - 2));
        out += text.substr(at, open - at);
        out += value != values.end() ? value->second : text.substr(open, close + 2 - open);
        at = close + 2;
    }
    return out + text.substr(at);
}

} // namespace

std::vector<Segment> reportSegments(const KitContent& content) {
    std::vector<Segment> document{titleSegment(content)};
    for (const LabOutcome& lab : content.grade.labs) appendLab(document, lab, content);
    return document;
}

std::string reportHtml(const std::vector<Segment>& document, const Words& words) {
    std::string body;
    for (const Segment& s : document)
        body += s.kind == Segment::Kind::Student
                    ? substitute(templates::kStudentTextHtml, {{"key", escapeMarkup(s.key)}, {"content", markdownToHtml(s.text)}})
                    : markdownToHtml(s.text);
    return substitute(templates::kReportHtml, {{"lang", words.lang},
                                               {"title", escapeMarkup(words.title)},
                                               {"style", templates::kReportCss},
                                               {"script", templates::kReportJs},
                                               {"body", body}});
}

} // namespace raylab::report
