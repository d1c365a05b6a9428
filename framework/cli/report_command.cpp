// raylab report: the student's lab report kit. Renders this build's figures, grades the pictures
// with the grader's image checks (framework/grader/, the same lines and heat maps as `raylab grade`),
// and writes DIR/report.md and a standalone DIR/report.html (every image beside it in DIR), a
// section per lab with the handout's figure numbers and an empty place for the student's own text.
#include "build_info.h"
#include "commands.h"

#include "grader/grade.h"
#include "grader/report.h"

#include "raylab/atomic_file.h"
#include "raylab/figure.h"
#include "raylab/image_io.h"
#include "raylab/messages.h"
#include "raylab/terminal.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstddef>
#include <filesystem>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace raylab::cli {

namespace {

namespace fs = std::filesystem;
using namespace raylab::grader;

// The report's words, in English or French.
struct Words {
    const char* title;
    const char* intro;
    const char* lab;
    const char* figure;
    const char* yours;
    const char* reference;
    const char* difference;
    const char* renderTime;
    const char* gradeLines;
    const char* yourText;
    const char* yourTextHint;
    const char* comparison;
    const char* comparisonIntro;
    const char* aliased;
    const char* antialiased;
    const char* zoom;
    const char* fullReport;
    const char* colon;
};

constexpr Words kEnglish{
    "Lab report",
    "Made by `raylab report`: each figure of the handout, yours beside the reference and a heat map of "
    "the difference, with its render time and the grader's verdict. Write your own text in the sections "
    "marked \"Your text\".",
    "Lab",
    "Figure",
    "yours",
    "reference",
    "difference",
    "render time",
    "Grade",
    "Your text",
    "Write here what you did, what the figures show and what went wrong.",
    "Antialiasing: aliased against antialiased",
    "Figure 3(c) (one ray per pixel) beside figure 6 (32 samples per pixel), and a close-up of the silhouette.",
    "aliased (figure 3(c))",
    "antialiased (figure 6)",
    "close-up of the silhouette, each pixel enlarged",
    "The grader's full report",
    ": ",
};

constexpr Words kFrench{
    "Compte rendu de TP",
    "Ce compte rendu a été produit par `raylab report` : il présente chaque figure de l'énoncé, la vôtre à "
    "côté de la référence et d'une carte de la différence, avec son temps de rendu et le verdict du "
    "correcteur. Écrivez votre propre texte dans les sections « Votre texte ».",
    "TP",
    "Figure",
    "la vôtre",
    "référence",
    "différence",
    "temps de rendu",
    "Évaluation",
    "Votre texte",
    "Écrivez ici ce que vous avez fait, ce que montrent les figures et ce qui n'a pas marché.",
    "Anticrénelage : avant et après",
    "La figure 3(c) (un rayon par pixel) à côté de la figure 6 (32 échantillons par pixel), et un gros plan "
    "sur la silhouette.",
    "sans anticrénelage (figure 3(c))",
    "avec anticrénelage (figure 6)",
    "gros plan sur la silhouette, chaque pixel agrandi",
    "Le rapport complet du correcteur",
    " : ",
};

struct ReportOptions {
    std::string out;
    std::string lang = "en";
};

// One figure as this build rendered it.
struct RenderedFigure {
    std::string id;
    int lab = 0;
    bool rendered = false;
    std::string message; // not done yet, or what failed
    double seconds = 0.;
};

std::string escape(const std::string& text) {
    std::string out;
    for (char c : text) switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    return out;
}

// Markdown's `code` as HTML, escaped.
std::string htmlText(const std::string& markdown) {
    std::string out;
    bool code = false;
    for (char c : markdown)
        if (c == '`') out += (code = !code) ? "<code>" : "</code>";
        else out += escape(std::string(1, c));
    return out;
}

std::string seconds(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f s", s);
    return text;
}

std::string pointsText(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

// The close-up: a w x h block of `image` from (x0, y0), each pixel enlarged to s x s.
Image8 zoom(const Image8& image, int x0, int y0, int w, int h, int s) {
    Image8 z{w * s, h * s, std::vector<std::uint8_t>(std::size_t(w * s) * std::size_t(h * s) * 3)};
    for (int j = 0; j < z.height; ++j)
        for (int i = 0; i < z.width; ++i) {
            const int si = std::clamp(x0 + i / s, 0, image.width - 1), sj = std::clamp(y0 + j / s, 0, image.height - 1);
            std::copy_n(image.pixel(si, sj), 3, &z.rgb[3 * (std::size_t(j) * std::size_t(z.width) + std::size_t(i))]);
        }
    return z;
}

// Where the close-up looks: the sphere's left edge a third of the way down the reference picture.
std::pair<int, int> silhouette(const Image8& reference) {
    for (int j : {reference.height / 3, reference.height / 2}) {
        const std::uint8_t* background = reference.pixel(0, j);
        for (int i = 1; i < reference.width; ++i) {
            const std::uint8_t* p = reference.pixel(i, j);
            if (std::abs(int(p[0]) - background[0]) + std::abs(int(p[1]) - background[1]) +
                    std::abs(int(p[2]) - background[2]) > 24)
                return {i, j};
        }
    }
    return {reference.width / 2, reference.height / 2};
}

// The grader's line for a figure, as `raylab grade` prints it.
std::string gradeLine(const FigureOutcome& f) {
    std::string line = std::string(f.passed ? "PASS" : "FAIL") + "  lab" + std::to_string(f.lab) + "  figure " + f.id +
                       ": " + f.reason;
    if (!f.diagnosis.empty()) line += "\n        " + f.diagnosis;
    return line;
}

struct Page {
    std::ostringstream md, html;
    void image(const std::string& src, const std::string& alt) {
        html << "<img src=\"" << escape(src) << "\" alt=\"" << escape(alt) << "\">";
    }
};

int runReport(const ReportOptions& o, const Context& context) {
    const Words& w = o.lang == "fr" ? kFrench : kEnglish;
    const fs::path out = o.out.empty() ? fs::path("out/report-kit") : fs::path(o.out);
    const fs::path figures = out / "figures", zooms = out / "zoom";
    fs::create_directories(figures);
    fs::create_directories(zooms);
    for (const fs::path& folder : {figures, zooms}) // no stale picture of an earlier run
        for (const auto& entry : fs::directory_iterator(folder))
            if (entry.path().extension() == ".png") fs::remove(entry.path());

    // 1. Render this build's figures.
    std::printf("raylab report, %s build (%s) -> %s\n", build::kImpl, build::kLabOrigins, out.string().c_str());
    std::vector<RenderedFigure> rendered;
    const RenderOptions renderOptions{context.threads, stderrIsInteractive()};
    for (const SceneDescription& d : loadSceneFolder(context.scenes)) {
        const FigureResult r = renderScene(d, renderOptions);
        RenderedFigure f{d.id, d.lab, r.status == FigureResult::Status::Rendered, r.message, r.stats.seconds};
        if (f.rendered) writePng(figures / (d.id + ".png"), quantize(*r.image));
        else if (r.status == FigureResult::Status::Failed) f.message = "failed: " + r.message;
        std::printf("  %-24s %s\n", d.id.c_str(), f.rendered ? seconds(f.seconds).c_str() : f.message.c_str());
        rendered.push_back(std::move(f));
    }

    // 2. Grade the pictures: the grader's image checks, its report (heat maps) in DIR/grade/.
    std::random_device random;
    const fs::path scratch = fs::temp_directory_path() / ("raylab-report-" + std::to_string(random()));
    fs::create_directories(scratch);
    const GradeSetup setup = loadGradeSetup(referencesFolder(), labsFolder(), context.scenes, scratch);
    const LabCatalog& catalog = setup.labs;
    GradeResult result = gradeImages(setup, figures);
    result.title = "raylab report: the image checks of your figures";
    writeReports(result, setup.references, out / "grade");
    fs::remove_all(scratch);
    std::map<std::string, const FigureOutcome*> outcomes;
    for (const FigureOutcome& f : result.figures) outcomes[f.id] = &f;

    // In the handout's order (the labs' descriptions: 3(a), 3(b), 3(c) ...), the figures it does not number last.
    std::map<std::string, std::size_t> handoutOrder;
    for (const LabDescription& lab : catalog.labs)
        for (const LabFigure& f : lab.figures) handoutOrder.emplace(f.id, handoutOrder.size());
    const auto order = [&](const RenderedFigure& f) {
        const auto it = handoutOrder.find(f.id);
        return it != handoutOrder.end() ? it->second : handoutOrder.size();
    };
    std::stable_sort(rendered.begin(), rendered.end(),
                     [&](const RenderedFigure& a, const RenderedFigure& b) { return order(a) < order(b); });
    // The antialiasing comparison closes the section of the lab that draws the antialiased figure.
    const LabDescription* comparisonLab = catalog.figure("lab3_cosine") ? catalog.labOfFigure("lab5_antialiased") : nullptr;

    // 3. The pages.
    Page page;
    std::ostringstream& md = page.md;
    std::ostringstream& html = page.html;
    md << "# " << w.title << "\n\n" << w.intro << "\n\n";
    html << "<!doctype html>\n<html lang=\"" << o.lang << "\"><head><meta charset=\"utf-8\"><title>" << escape(w.title)
         << "</title>\n<style>body{font-family:sans-serif;max-width:1300px;margin:auto;padding:0 1em}"
            "figure{display:inline-block;margin:0 8px 8px 0;vertical-align:top}"
            "img{width:300px;image-rendering:pixelated;border:1px solid #ccc}img.zoom{width:400px}"
            "figcaption{font-size:90%}.todo{color:#a60}.pass{color:#080}.fail{color:#b00}"
            "pre{white-space:pre-wrap;background:#f6f6f6;padding:6px}"
            ".your-text{border:2px dashed #999;padding:0 1em;min-height:6em}</style>\n"
            "<script>\n"
            "var raylabErrors = [];\n"
            "window.addEventListener('error', function (e) { if (!(e.target instanceof HTMLImageElement))"
            " raylabErrors.push(String(e.message)); }, true);\n"
            "window.addEventListener('load', function () {\n"
            "  var broken = [];\n"
            "  for (var k = 0; k < document.images.length; ++k) {\n"
            "    var img = document.images[k];\n"
            "    if (!img.complete || img.naturalWidth === 0) broken.push(img.getAttribute('src'));\n"
            "  }\n"
            "  var ok = broken.length === 0 && raylabErrors.length === 0 && document.images.length > 0;\n"
            "  document.getElementById('image-check').textContent = 'image check: ' + (ok ? 'ok' : 'FAILED') + ', ' +\n"
            "    document.images.length + ' images, broken: [' + broken.join(', ') + '], errors: [' +\n"
            "    raylabErrors.join(' | ') + ']';\n"
            "});\n"
            "</script></head><body>\n<h1>"
         << escape(w.title) << "</h1>\n<p>" << htmlText(w.intro) << "</p>\n<p><a href=\"grade/index.html\">"
         << escape(w.fullReport) << "</a></p>\n";
    md << "[" << w.fullReport << "](grade/index.html)\n\n";

    for (const LabOutcome& points : result.labs) {
        const int lab = points.lab;
        const LabDescription* description = catalog.lab(lab);
        const std::string labTitle =
            std::string(w.lab) + " " + std::to_string(lab) + (description ? w.colon + description->title(o.lang) : "");
        md << "## " << labTitle << "\n\n";
        html << "<section id=\"lab" << lab << "\"><h2>" << escape(labTitle) << "</h2>\n";
        std::string lines;
        for (const RenderedFigure& f : rendered) {
            if (f.lab != lab) continue;
            const LabFigure* h = catalog.figure(f.id);
            const std::string number = h ? h->handout : "-";
            const std::string caption = h ? h->caption(o.lang) : "";
            const std::string heading = std::string(w.figure) + " " + number + " (" + f.id + ")";
            md << "### " << heading << "\n\n" << caption << "\n\n";
            html << "<h3 id=\"" << escape(f.id) << "\">" << escape(heading) << "</h3>\n<p>" << escape(caption) << "</p>\n";
            const FigureOutcome* g = outcomes.count(f.id) ? outcomes[f.id] : nullptr;
            const bool hasReference = setup.references.find(f.id) != nullptr;
            const bool hasDiff = g && !g->verdict.error.empty();
            if (f.rendered) {
                md << "| " << w.yours << " | " << w.reference << " | " << w.difference << " |\n|---|---|---|\n| ![" << f.id
                   << "](figures/" << f.id << ".png) | ";
                if (hasReference) md << "![" << f.id << " reference](grade/images/" << f.id << ".reference.png)";
                md << " | ";
                if (hasDiff) md << "![" << f.id << " difference](grade/images/" << f.id << ".diff.png)";
                md << " |\n\n" << w.renderTime << ": " << seconds(f.seconds) << "\n\n";
                html << "<figure>";
                page.image("figures/" + f.id + ".png", f.id);
                html << "<figcaption>" << escape(w.yours) << "</figcaption></figure>";
            } else {
                md << "**" << f.message << "**\n\n";
                if (hasReference) md << w.reference << ":\n\n![" << f.id << " reference](grade/images/" << f.id << ".reference.png)\n\n";
                html << "<p class=\"todo\"><b>" << escape(f.message) << "</b></p>\n";
            }
            if (hasReference) {
                html << "<figure>";
                page.image("grade/images/" + f.id + ".reference.png", f.id + " reference");
                html << "<figcaption>" << escape(w.reference) << "</figcaption></figure>";
            }
            if (hasDiff) {
                html << "<figure>";
                page.image("grade/images/" + f.id + ".diff.png", f.id + " difference");
                html << "<figcaption>" << escape(w.difference) << "</figcaption></figure>";
            }
            html << "\n";
            if (f.rendered) html << "<p>" << escape(w.renderTime) << ": " << seconds(f.seconds) << "</p>\n";
            if (g) lines += gradeLine(*g) + "\n";
        }
        if (description != nullptr && description == comparisonLab) { // the antialiasing comparison: figure 3(c) against figure 6, and a close-up
            md << "### " << w.comparison << "\n\n" << w.comparisonIntro << "\n\n";
            html << "<h3 id=\"antialiasing-comparison\">" << escape(w.comparison) << "</h3>\n<p>"
                 << escape(w.comparisonIntro) << "</p>\n";
            const FigureReference* shape = setup.references.find("lab3_cosine");
            const auto [cx, cy] = shape ? silhouette(shape->image) : std::pair<int, int>{0, 0};
            md << "| " << w.aliased << " | " << w.antialiased << " |\n|---|---|\n|";
            std::string zoomRow = "|";
            for (const char* id : {"lab3_cosine", "lab5_antialiased"}) {
                const auto it = std::find_if(rendered.begin(), rendered.end(), [&](const auto& f) { return f.id == id; });
                html << "<figure>";
                if (it != rendered.end() && it->rendered) {
                    const std::string full = std::string("figures/") + id + ".png", close = std::string("zoom/") + id + ".png";
                    writePng(out / close, zoom(readImage(out / full), cx - 20, cy - 14, 40, 28, 10));
                    md << " ![" << id << "](" << full << ") |";
                    zoomRow += " ![" + std::string(id) + " close-up](" + close + ") |";
                    page.image(full, id);
                    html << "<br>";
                    html << "<img class=\"zoom\" src=\"" << close << "\" alt=\"" << id << " close-up\">";
                } else {
                    const std::string message = it != rendered.end() ? it->message : std::string("no figure ") + id;
                    md << " **" << message << "** |";
                    zoomRow += " |";
                    html << "<p class=\"todo\"><b>" << escape(message) << "</b></p>";
                }
                html << "<figcaption>" << escape(std::string(id) == "lab3_cosine" ? w.aliased : w.antialiased)
                     << "</figcaption></figure>";
            }
            md << "\n" << zoomRow << "\n\n" << w.zoom << "\n\n";
            html << "\n<p>" << escape(w.zoom) << "</p>\n";
        }
        lines += "lab " + std::to_string(lab) + ": " + pointsText(points.points) + " / " + pointsText(points.maxPoints) +
                 " points (figures)\n";
        md << "### " << w.gradeLines << "\n\n```text\n" << lines << "```\n\n";
        html << "<h3>" << escape(w.gradeLines) << "</h3>\n<pre>" << escape(lines) << "</pre>\n";
        md << "### " << w.yourText << " (" << w.lab << " " << lab << ")\n\n<!-- raylab:your-text lab=" << lab << " -->\n"
           << "*" << w.yourTextHint << "*\n\n";
        html << "<section class=\"your-text\" id=\"your-text-lab" << lab << "\"><h3>" << escape(w.yourText)
             << "</h3><p><i>" << escape(w.yourTextHint) << "</i></p></section>\n</section>\n";
    }
    html << "<pre id=\"image-check\" hidden>image check: not run</pre>\n</body></html>\n";

    writeFileAtomically(out / "report.md", md.str());
    writeFileAtomically(out / "report.html", html.str());
    std::printf("%s", terminalSummary(result).c_str());
    std::printf("report: %s and %s (the grader's report: %s)\n", (out / "report.md").string().c_str(),
                (out / "report.html").string().c_str(), (out / "grade" / "index.html").string().c_str());
    return 0;
}

} // namespace

void addReportCommand(CLI::App& app, Context& context) {
    auto o = std::make_shared<ReportOptions>();
    CLI::App* report = app.add_subcommand(
        "report", "your lab report kit: renders and grades your figures into DIR/report.md and DIR/report.html");
    report->add_option("--out", o->out, "the report's folder (default: out/report-kit)");
    context.addImplOption(report);
    context.addRenderOptions(report);
    report->callback([&context, o] {
        o->lang = languageCode(language()); // the global --lang, or the environment's (raylab/messages.h)
        if (!context.ranInOtherImpl()) context.exitStatus = runReport(*o, context);
    });
}

} // namespace raylab::cli
