#include "report/report_kit.h"

#include "grader/judge/grade.h"
#include "grader/course/grade_reports.h"
#include "grader/course/submission.h"
#include "grader/sandbox/install_command.h"
#include "src/atomic_file.h"
#include "src/figure.h"
#include "src/text.h"
#include "raylab/image_io.h"
#include "report/difference_map.h"
#include "report/pdf.h"
#include "report/report_pages.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <random>
#include <stdexcept>

namespace raylab::report {

namespace {

namespace fs = std::filesystem;
using namespace raylab::grader;

// The kit's picture folders, without an earlier run's pictures.
void prepareFolders(const fs::path& out) {
    for (const char* name : {"figures", "zoom", "diff"}) {
        fs::create_directories(out / name);
        for (const auto& entry : fs::directory_iterator(out / name))
            if (entry.path().extension() == ".png") fs::remove(entry.path());
    }
}

// This build's figures into OUT/figures, in the handout's order (the figures it does not number last).
std::vector<KitFigure> renderFigures(const ReportRequest& request, const LabCatalog& labs, std::map<std::string, Image8>& images,
                                     const Words& words) {
    std::map<std::string, std::size_t> handoutOrder;
    for (const LabDescription& lab : labs.labs)
        for (const LabFigure& f : lab.figures) handoutOrder.emplace(f.id, handoutOrder.size());
    std::vector<KitFigure> figures;
    for (const SceneDescription& d : loadFiguresInLabOrder(request.scenes, labs)) {
        const FigureResult r = renderScene(d, RenderOptions{request.threads, request.progress});
        KitFigure f{d.id, labs.labNumberOfFigure(d.id), r.status == FigureResult::Status::Rendered, r.message, r.stats, d.width, d.height};
        if (r.status == FigureResult::Status::Failed) f.message = tr("figures.failed", {{"message", r.message}});
        if (r.status == FigureResult::Status::NotDoneYet) f.message = waitingMessage(labs, d.id, *r.todo);
        if (f.rendered) {
            images[d.id] = quantize(*r.image);
            writePng(request.out / "figures" / (d.id + ".png"), images[d.id]);
        }
        std::printf("  %-24s %s\n", d.id.c_str(), f.rendered ? seconds(f.stats.seconds, words).c_str() : f.message.c_str());
        figures.push_back(std::move(f));
    }
    const auto order = [&](const KitFigure& f) {
        const auto it = handoutOrder.find(f.id);
        return it != handoutOrder.end() ? it->second : handoutOrder.size();
    };
    std::stable_sort(figures.begin(), figures.end(), [&](const KitFigure& a, const KitFigure& b) { return order(a) < order(b); });
    return figures;
}

// The code graded as `raylab grade` grades it: this build's agents (the reference's for raylab-reference).
GradeResult gradeCodeOfThisBuild(const ReportRequest& request, const GradeSetup& setup, const Words& words) {
    bool isolated = false;
    std::vector<AgentPlan> agents;
    if (request.referenceBuild) agents.push_back({request.programs / "raylab-agent-reference", 0});
    else agents = findAgents(request.programs, setup.labs.numbers(), isolated);
    std::erase_if(agents, [&](const AgentPlan& a) {
        return std::find(request.unbuilt.begin(), request.unbuilt.end(), a.lab) != request.unbuilt.end();
    });
    if (agents.empty() && request.unbuilt.empty())
        throw std::runtime_error(tr("grade.no_agent", {{"folder", request.programs.string()}}));
    GradeResult result = gradeCode(setup, agents, isolated, request.unbuilt, request.buildMessage);
    result.title = words.text("grade_title");
    return result;
}

// Each figure's grade, and a difference map (OUT/diff) of this build's picture against its reference.
void compareFigures(std::vector<KitFigure>& figures, const std::map<std::string, Image8>& images, const GradeResult& result,
                    const ReferenceSet& references, const fs::path& out) {
    writePng(out / "diff" / "scale.png", differenceScale());
    for (KitFigure& f : figures) {
        for (const FigureOutcome& g : result.figures)
            if (g.id == f.id) f.grade = &g;
        const FigureReference* reference = references.find(f.id);
        f.hasReference = reference != nullptr;
        const auto image = images.find(f.id);
        if (reference == nullptr || image == images.end()) continue;
        f.statistical = reference->stats.has_value();
        if (f.statistical) f.outlierZ = reference->stats->outlierZ;
        writePng(out / "diff" / (f.id + ".png"), differenceMap(image->second, *reference, compareImage(*reference, image->second)));
        f.hasDifference = true;
    }
}

// Where the close-up looks: the sphere's left edge a third of the way down the reference picture.
std::pair<int, int> silhouette(const Image8& reference) {
    for (int j : {reference.height / 3, reference.height / 2}) {
        const std::uint8_t* background = reference.pixel(0, j);
        for (int i = 1; i < reference.width; ++i) {
            const std::uint8_t* p = reference.pixel(i, j);
            if (std::abs(int(p[0]) - background[0]) + std::abs(int(p[1]) - background[1]) + std::abs(int(p[2]) - background[2]) > 24)
                return {i, j};
        }
    }
    return {reference.width / 2, reference.height / 2};
}

// The block of `image` the close-up shows, each pixel enlarged to zoom x zoom.
Image8 enlarge(const Image8& image, const CloseUp& z) {
    Image8 big{z.width * z.zoom, z.height * z.zoom, {}};
    big.rgb.reserve(std::size_t(big.width) * std::size_t(big.height) * 3);
    for (int j = 0; j < big.height; ++j)
        for (int i = 0; i < big.width; ++i) {
            const std::uint8_t* p = image.pixel(std::min(z.x + i / z.zoom, image.width - 1), std::min(z.y + j / z.zoom, image.height - 1));
            big.rgb.insert(big.rgb.end(), p, p + 3);
        }
    return big;
}

// The antialiasing comparison's close-ups (OUT/zoom), at the aliased reference's silhouette.
std::optional<CloseUp> cropCloseUps(const std::map<std::string, Image8>& images, const ReferenceSet& references,
                                    const std::vector<SceneDescription>& described, const fs::path& scenes,
                                    const fs::path& out) {
    // A course without both roles has no comparison (two scenes with one role is an error).
    const auto hasRole = [&](const char* role) {
        return std::any_of(described.begin(), described.end(), [&](const SceneDescription& d) {
            return std::find(d.roles.begin(), d.roles.end(), role) != d.roles.end();
        });
    };
    if (!hasRole("aliased") || !hasRole("antialiased")) return std::nullopt;
    const std::string aliased = sceneWithRole(described, "aliased", scenes).id,
                      antialiased = sceneWithRole(described, "antialiased", scenes).id;
    const FigureReference* shape = references.find(aliased);
    if (shape == nullptr || references.find(antialiased) == nullptr) return std::nullopt;
    const auto [cx, cy] = silhouette(shape->image);
    CloseUp z{0, 0, 40, 28, 10, aliased, antialiased};
    z.x = std::clamp(cx - z.width / 2, 0, std::max(0, shape->image.width - z.width));
    z.y = std::clamp(cy - z.height / 2, 0, std::max(0, shape->image.height - z.height));
    for (const std::string& id : {aliased, antialiased}) {
        const auto image = images.find(id);
        if (image != images.end()) writePng(out / "zoom" / (id + ".png"), enlarge(image->second, z));
    }
    return z;
}

// report.md and report.html: this run's generated parts around the student's text of report.md.
void writePages(const KitContent& content, const fs::path& out, const fs::path& treeOut) {
    const fs::path markdown = out / "report.md";
    PreviousText previous;
    if (fs::exists(markdown)) {
        const std::optional<std::string> read = readWholeFile(markdown);
        if (!read) throw std::runtime_error("cannot read " + printablePath(markdown));
        const std::string& old = *read;
        writeFileAtomically(out / "report.previous.md", old); // one undo, whatever happens next
        previous = readPreviousText(old, content.words);
    }
    std::vector<UnplacedText> moved;
    const std::vector<Segment> document = placeStudentText(reportSegments(content), previous, content.words, &moved);
    writeFileAtomically(markdown, toMarkdown(document));
    std::vector<std::string> leftOut;
    const ImageSources images{out / "report.html", {out, treeOut}};
    writeFileAtomically(out / "report.html", reportHtml(document, content.words, images, leftOut));
    std::printf("%s", movedTextNotice(moved, markdown.string(), content.words).c_str()); // the student must know
    for (const std::string& address : leftOut)
        std::printf("%s\n", content.words.text("image_left_out_notice", {{"file", printablePath(markdown)}, {"address", printableName(address)},
                                                                          {"kit", printablePath(out)}, {"out", printablePath(treeOut)}})
                                .c_str());
}

int printPdf(const fs::path& out, const Words& words) {
    const std::optional<fs::path> chromium = findChromium();
    if (!chromium) {
        std::printf("%s\n", words.text("no_chromium", {{"install", grader::installCommand("chromium", "--cask chromium",
                                                                                    "winget install Microsoft.Edge")}})
                                .c_str());
        return 1;
    }
    printToPdf(*chromium, out / "report.html", out / "report.pdf", words);
    std::printf("%s\n", words.text("pdf_written", {{"file", (out / "report.pdf").string()}}).c_str());
    return 0;
}

} // namespace

int writeReportKit(const ReportRequest& request) {
    const fs::path& out = request.out;
    const Words& words = wordsFor(request.lang);
    fs::create_directories(out);
    const TitleBlock title = readTitleBlock(out / "report.toml", words); // its errors before any render
    prepareFolders(out);

    std::random_device random;
    const fs::path scratch = fs::temp_directory_path() / ("raylab-report-" + std::to_string(random()));
    fs::create_directories(scratch);
    GradeSetup setup = loadGradeSetup(request.references, request.labs, request.scenes, scratch);
    setup.threads = request.threads;
    std::map<std::string, Image8> images;
    std::vector<KitFigure> figures = renderFigures(request, setup.labs, images, words);
    const GradeResult result = gradeCodeOfThisBuild(request, setup, words);
    writeReports(result, setup.references, out / "grade");
    fs::remove_all(scratch);
    compareFigures(figures, images, result, setup.references, out);
    const std::optional<CloseUp> closeUp = cropCloseUps(images, setup.references, loadFiguresInLabOrder(request.scenes, setup.labs),
                                                        request.scenes.empty() ? request.labs : request.scenes, out);
    writePages(KitContent{words, title, result, setup.labs, std::move(figures), closeUp}, out, request.treeOut);

    std::printf("%s", terminalSummary(result).c_str());
    if (title.placeholders) std::printf("%s\n", words.text("fill_title_block", {{"file", (out / "report.toml").string()}}).c_str());
    std::printf("%s\n", words.text("written", {{"markdown", (out / "report.md").string()},
                                              {"html", (out / "report.html").string()},
                                              {"grade", (out / "grade" / "index.html").string()}})
                            .c_str());
    return request.pdf ? printPdf(out, words) : 0;
}

} // namespace raylab::report
