#include "report/report_pages.h"

#include "report/difference_map.h"
#include "report/templates.h"

#include "grader/judge/checks/checks.h"
#include "src/markup.h"
#include "src/messages.h"

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

// "**Name**: value" ("**Nom** : valeur" in French): the colon outside, where CommonMark lets the bold close.
std::string boldField(const std::string& label, const std::string& value, const Words& w) {
    return w.text("labelled", {{"label", "**" + label + "**"}, {"value", value}});
}

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
    return w.text("total_detail", {{"checks", number(checks, -1, w)}, {"checks_max", number(checksMax, -1, w)},
                                   {"figures", number(figures, -1, w)}, {"figures_max", number(figuresMax, -1, w)}});
}

Segment titleSegment(const KitContent& c) {
    const Words& w = c.words;
    const TitleBlock& t = c.title;
    std::string text = std::string("# ") + w.text("title") + "\n\n";
    text += "- " + boldField(w.text("name"), markdownText(t.name), w) + "\n";
    text += "- " + boldField(w.text("group"), markdownText(t.group), w) + "\n";
    text += "- " + boldField(w.text("course"), markdownText(t.course), w) + "\n";
    text += "- " + boldField(w.text("date"), markdownText(t.date), w) + "\n";
    const std::string total = "**" + number(c.grade.score(), -1, w) + " / " + number(c.grade.maxScore(), -1, w) + "** (" +
                              pointsDetail(c.grade, 0, w) + ")";
    text += "- " + boldField(w.text("total"), total, w) + "\n\n";
    text += w.text("intro") + "\n\n[" + w.text("full_report") + "](grade/index.html)\n";
    return {Segment::Kind::Generated, "title", text};
}

// The one-line reading of a difference map, with its scale.
std::string differenceReading(const KitFigure& f, const Words& w) {
    std::string line = w.text("scale_reading", {{"scale", "![scale](diff/scale.png)"}, {"lsb", std::to_string(kScaleFullLsb)}});
    if (f.statistical) {
        line += ' ';
        line += w.text("statistical_reading", {{"z", number(f.outlierZ, -1, w)}});
    }
    return line + "\n\n";
}

std::string figureMarkdown(const KitFigure& f, const KitContent& c) {
    const Words& w = c.words;
    const grader::LabFigure* handout = c.labs.figure(f.id);
    std::string text = std::string("### ") + w.text("figure") + " " + (handout ? handout->handout : "-") + " (" + f.id + ")\n\n";
    if (handout) text += handout->caption(w.code()) + "\n\n";
    if (!f.rendered) text += "**" + f.message + "**\n\n";
    text += w.text("pictures_row") + "\n\n";
    if (f.rendered) text += "![" + f.id + "](figures/" + f.id + ".png) ";
    if (f.hasReference) text += "![" + f.id + " reference](grade/images/" + f.id + ".reference.png) ";
    if (f.hasDifference) text += "![" + f.id + " difference](diff/" + f.id + ".png)";
    text += "\n\n";
    text += f.hasDifference ? differenceReading(f, w) : std::string("*") + w.text("no_difference") + "*\n\n";
    if (f.rendered)
        text += w.text("labelled", {{"label", w.text("render_time")}, {"value", seconds(f.stats.seconds, w)}}) + "\n\n";
    return text;
}

// The grader's lines for a check and a figure, as `raylab grade` says them (grader/course/grade_reports.cpp).
std::string verdictAndLab(bool passed, int lab) {
    return tr(passed ? "report.pass" : "report.fail") + "  " + tr("report.lab_short", {{"lab", std::to_string(lab)}}) + "  ";
}

std::string checkLine(const CheckOutcome& k, const Words& w) {
    std::string line = verdictAndLab(k.passed, k.lab) + tr("report.check_line", {{"name", titleInLanguage(k.name)}}) + " (" +
                       number(k.points, -1, w) + " / " + number(k.maxPoints, -1, w) + ")\n";
    if (!k.passed && !k.message.empty()) line += "        " + k.message + "\n";
    return line;
}

std::string figureLine(const FigureOutcome& f) {
    std::string line = verdictAndLab(f.passed, f.lab) + tr("report.figure_line", {{"id", f.id}, {"reason", f.reason}}) + "\n";
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
    lines += w.text("labelled", {{"label", tr("report.lab", {{"lab", std::to_string(lab.lab)}})},
                                 {"value", number(lab.points, -1, w) + " / " + number(lab.maxPoints, -1, w) + " (" +
                                               pointsDetail(c.grade, lab.lab, w) + ")"}}) +
             "\n";
    for (const std::string& note : lab.notes) lines += tr("grade.note", {{"note", note}}) + "\n";
    return std::string("### ") + w.text("grade") + "\n\n```text\n" + lines + "```\n\n";
}

const KitFigure* findFigure(const KitContent& c, const std::string& id) {
    for (const KitFigure& f : c.figures)
        if (f.id == id) return &f;
    return nullptr;
}

std::string costLine(const KitFigure& f, const std::string& label, const Words& w) {
    const double pixels = double(f.width) * double(f.height);
    const double samples = pixels > 0 ? double(f.stats.primaryRays) / pixels : 0.;
    return std::string("- ") + w.text("cost", {{"label", label}, {"samples", number(samples, -1, w)},
                                  {"rays", std::to_string(f.stats.primaryRays)}, {"time", seconds(f.stats.seconds, w)}}) + "\n";
}

std::string comparisonMarkdown(const KitContent& c) {
    const Words& w = c.words;
    const CloseUp& z = *c.closeUp;
    std::string text = std::string("### ") + w.text("comparison") + "\n\n" + w.text("comparison_intro") + "\n\n";
    std::string pictures, closeUps, costs;
    for (const auto& [id, label] : {std::pair{z.aliased, w.text("aliased")}, std::pair{z.antialiased, w.text("antialiased")}}) {
        const KitFigure* f = findFigure(c, id);
        if (f == nullptr || !f->rendered) {
            pictures += std::string("**") + (f ? f->message : std::string("no figure ") + id) + "** ";
            continue;
        }
        pictures += "![" + label + "](figures/" + id + ".png) ";
        closeUps += "![" + std::string(id) + " close-up](zoom/" + id + ".png) ";
        costs += costLine(*f, label, w);
    }
    text += pictures + "\n\n" + costs + "\n" + closeUps + "\n\n";
    const KitFigure* aliased = findFigure(c, z.aliased);
    text += w.text("close_up", {{"x_first", std::to_string(z.x)}, {"x_last", std::to_string(z.x + z.width - 1)},
                                 {"y_first", std::to_string(z.y)}, {"y_last", std::to_string(z.y + z.height - 1)},
                                 {"width", std::to_string(aliased ? aliased->width : 0)},
                                 {"height", std::to_string(aliased ? aliased->height : 0)}, {"zoom", std::to_string(z.zoom)}}) +
            "\n";
    return text;
}

bool drawsComparison(const KitContent& c, int lab) {
    if (!c.closeUp) return false;
    const grader::LabDescription* owner = c.labs.labOfFigure(c.closeUp->antialiased);
    return owner != nullptr && owner->number == lab;
}

void appendLab(std::vector<Segment>& document, const LabOutcome& lab, const KitContent& c) {
    const Words& w = c.words;
    const grader::LabDescription* description = c.labs.lab(lab.lab);
    const std::string heading = w.text("lab") + " " + std::to_string(lab.lab);
    std::string text = std::string("## ") +
                       (description ? w.text("labelled", {{"label", heading}, {"value", description->title(w.code())}}) : heading) +
                       "\n\n";
    for (const KitFigure& f : c.figures)
        if (f.lab == lab.lab) text += figureMarkdown(f, c);
    if (drawsComparison(c, lab.lab)) text += comparisonMarkdown(c);
    text += gradeMarkdown(lab, c);
    text += std::string("### ") + w.text("your_text") + " (" + heading + ")\n";
    const std::string key = "lab" + std::to_string(lab.lab);
    document.push_back({Segment::Kind::Generated, key, text});
    document.push_back({Segment::Kind::Student, key, std::string("*") + w.text("your_text_hint") + "*\n"});
}

// Markdown to HTML by cmark, safe: raw HTML and javascript: links are left out, and so is an image from
// outside the allowed folders (image_sources.h): a line of text in its place says so, and its address
// goes to `leftOut`.
std::string markdownToHtml(const std::string& markdown, const ImageSources& images, const Words& words,
                           std::vector<std::string>& leftOut) {
    const std::unique_ptr<cmark_node, decltype(&cmark_node_free)> document(
        cmark_parse_document(markdown.c_str(), markdown.size(), CMARK_OPT_DEFAULT | CMARK_OPT_SMART), &cmark_node_free);
    if (!document) return "";
    std::vector<cmark_node*> refused; // replaced after the walk, which a change would disturb
    const std::unique_ptr<cmark_iter, decltype(&cmark_iter_free)> walk(cmark_iter_new(document.get()), &cmark_iter_free);
    for (cmark_event_type event; (event = cmark_iter_next(walk.get())) != CMARK_EVENT_DONE;) {
        cmark_node* node = cmark_iter_get_node(walk.get());
        if (event != CMARK_EVENT_ENTER || cmark_node_get_type(node) != CMARK_NODE_IMAGE) continue;
        const char* url = cmark_node_get_url(node);
        if (!imageAllowed(url != nullptr ? url : "", images)) refused.push_back(node);
    }
    for (cmark_node* image : refused) {
        const char* url = cmark_node_get_url(image);
        leftOut.emplace_back(url != nullptr ? url : "");
        cmark_node* note = cmark_node_new(CMARK_NODE_TEXT);
        cmark_node_set_literal(note, words.text("image_left_out", {{"address", leftOut.back()}}).c_str());
        cmark_node_replace(image, note);
        cmark_node_free(image);
    }
    const std::unique_ptr<char, decltype(&std::free)> html(cmark_render_html(document.get(), CMARK_OPT_DEFAULT | CMARK_OPT_SMART),
                                                           &std::free);
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

std::string reportHtml(const std::vector<Segment>& document, const Words& words, const ImageSources& images,
                       std::vector<std::string>& leftOut) {
    std::string body;
    for (const Segment& s : document) {
        const std::string html = markdownToHtml(s.text, images, words, leftOut);
        body += s.kind == Segment::Kind::Student ? substitute(templates::kStudentTextHtml, {{"key", escapeMarkup(s.key)}, {"content", html}})
                                                 : html;
    }
    return substitute(templates::kReportHtml, {{"lang", words.code()},
                                               {"title", escapeMarkup(words.text("title"))},
                                               {"style", templates::kReportCss},
                                               {"script", templates::kReportJs},
                                               {"body", body}});
}

} // namespace raylab::report
