// raylab report, as a student runs it: the reference build's kit has every figure, its handout
// number, its pictures and maps with their scale, the grade of the code (the same total as `raylab
// grade`); the student build (stubs) reports each lab as not done yet; a re-run keeps the student's
// text; the title block comes from report.toml; --pdf prints a PDF with chromium.
#include "support/files.h"
#include <doctest/doctest.h>

#include <algorithm>

#include "grader/lab_catalog.h"
#include "raylab/image_io.h"
#include "support/course.h"
#include "support/needs.h"
#include "support/run_program.h"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <utility>
#include <vector>

namespace fs = std::filesystem;

namespace {

// The course's labs, as the catalogue reads them.
const raylab::grader::LabCatalog& courseLabs() {
    static const raylab::grader::LabCatalog labs = raylab::grader::loadLabCatalog(RAYLAB_LABS_DIR);
    return labs;
}

// Every figure of the course, with its lab.
std::vector<std::pair<const raylab::grader::LabDescription*, const raylab::grader::LabFigure*>> courseFigures() {
    std::vector<std::pair<const raylab::grader::LabDescription*, const raylab::grader::LabFigure*>> figures;
    for (const raylab::grader::LabDescription& lab : courseLabs().labs)
        for (const raylab::grader::LabFigure& f : lab.figures) figures.emplace_back(&lab, &f);
    return figures;
}

using raylab::test::readFile;

void write(const fs::path& file, const std::string& text) { std::ofstream(file, std::ios::binary) << text; }

std::string program(const char* name) { return (fs::path(RAYLAB_BIN_DIR) / name).string(); }

// Runs `argv` (its output in DIR/output.txt); returns its exit status.
int run(const std::vector<std::string>& argv, const fs::path& dir) {
    return raylab::test::runProgram(argv, dir / "output.txt").status;
}

fs::path kitFolder(const std::string& name, bool fresh = true) {
    const fs::path dir = fs::path(RAYLAB_REPORT_TEST_DIR) / name;
    if (fresh) fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// Runs `PROGRAM report --out DIR ARGS` (the kit is also where the browser test looks).
fs::path runKit(const char* name, const fs::path& dir, const std::vector<std::string>& args = {}) {
    std::vector<std::string> argv{program(name), "report", "--threads", "2", "--out", dir.string()};
    argv.insert(argv.end(), args.begin(), args.end());
    const int status = run(argv, dir);
    REQUIRE_MESSAGE(status == 0, readFile(dir / "output.txt"));
    REQUIRE(fs::exists(dir / "report.md"));
    REQUIRE(fs::exists(dir / "report.html"));
    return dir;
}

// The same in a new folder.
fs::path makeKit(const char* name, const std::string& kit, const std::vector<std::string>& args = {}) {
    return runKit(name, kitFolder(kit), args);
}

// Every image the page names, by the pattern of its links.
std::vector<std::string> images(const std::string& text, const std::regex& pattern) {
    std::vector<std::string> found;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), pattern); it != std::sregex_iterator(); ++it)
        found.push_back((*it)[1].str());
    return found;
}

void checkImagesExist(const fs::path& dir, const std::string& md, const std::string& html) {
    const auto mdImages = images(md, std::regex(R"re(!\[[^\]]*\]\(([^)]+)\))re"));
    const auto htmlImages = images(html, std::regex(R"re(<img[^>]* src="([^"]+)")re"));
    CHECK(!mdImages.empty());
    CHECK(mdImages.size() == htmlImages.size());
    for (const std::vector<std::string>* list : {&mdImages, &htmlImages})
        for (const std::string& src : *list) {
            CHECK_MESSAGE(fs::is_regular_file(dir / src), src);
            CHECK_MESSAGE(src.find("://") == std::string::npos, src); // standalone: nothing from a network
            CHECK_MESSAGE(!fs::path(src).is_absolute(), src);
        }
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

// "total: X / Y" as `raylab grade` prints it.
std::string gradeTotal(const std::string& output) {
    std::smatch m;
    REQUIRE_MESSAGE(std::regex_search(output, m, std::regex(R"(total: ([0-9.]+ / [0-9.]+))")), output);
    return m[1];
}

} // namespace

TEST_SUITE("report") {

TEST_CASE("the reference build's kit: every figure, its number, its pictures and maps, a section per lab") {
    const fs::path dir = makeKit("raylab-reference", "reference");
    const std::string md = readFile(dir / "report.md"), html = readFile(dir / "report.html");
    const auto figures = courseFigures();
    for (const auto& [lab, figure] : figures) {
        const std::string& id = figure->id;
        CHECK_MESSAGE(html.find(id) != std::string::npos, id);
        CHECK_MESSAGE(md.find("Figure " + figure->handout + " (" + id + ")") != std::string::npos, figure->handout << " " << id);
        CHECK_MESSAGE(md.find("figures/" + id + ".png") != std::string::npos, id);
        CHECK_MESSAGE(md.find("diff/" + id + ".png") != std::string::npos, id);
        CHECK_MESSAGE(html.find("grade/images/" + id + ".reference.png") != std::string::npos, id);
        CHECK_MESSAGE(md.find("PASS  lab" + std::to_string(lab->number) + "  figure " + id + ":") != std::string::npos, id);
    }
    for (const int lab : courseLabs().numbers()) {
        CHECK(md.find("## Lab " + std::to_string(lab) + ": ") != std::string::npos);
        CHECK(md.find("### Your text (Lab " + std::to_string(lab) + ")\n<!-- raylab:end -->\n\n<!-- raylab:student lab" +
                      std::to_string(lab) + " -->") != std::string::npos);
        CHECK(html.find("id=\"your-text-lab" + std::to_string(lab) + "\"") != std::string::npos);
    }
    // The grade holds the function checks as well as the figures.
    CHECK(md.find("PASS  lab3  check ") != std::string::npos);
    CHECK(md.find("FAIL  lab") == std::string::npos);
    // Each difference map has its scale and its reading.
    CHECK(count(md, "](diff/scale.png) dark: within tolerance") == figures.size());
    CHECK(md.find("render time: ") != std::string::npos);
    CHECK(md.find("not done yet") == std::string::npos);
    CHECK(html.find("<pre id=\"image-check\" hidden>image check: not run</pre>") != std::string::npos);
    checkImagesExist(dir, md, html);
}

TEST_CASE("the grade block's total is `raylab grade`'s: the reference agent, and the student's stubs") {
    const fs::path reference = fs::path(RAYLAB_REPORT_TEST_DIR) / "reference";
    const fs::path graded = kitFolder("grade-reference");
    REQUIRE(run({program("raylab"), "grade", "--threads", "2", "--agent", program("raylab-agent-reference"), "--report",
                 (graded / "report").string()},
                graded) == 0);
    const std::string total = gradeTotal(readFile(graded / "output.txt"));
    CHECK(readFile(reference / "report.md").find("**Total grade**: **" + total + "** (") != std::string::npos);
    CHECK(gradeTotal(readFile(reference / "output.txt")) == total);

    const fs::path student = makeKit("raylab", "student");
    const fs::path stubs = kitFolder("grade-student");
    run({program("raylab"), "grade", "--threads", "2", "--report", (stubs / "report").string()}, stubs);
    const std::string stubTotal = gradeTotal(readFile(stubs / "output.txt"));
    CHECK(readFile(student / "report.md").find("**Total grade**: **" + stubTotal + "** (") != std::string::npos);
}

TEST_CASE("the student build's kit (stubs): each lab not done yet, the references still shown") {
    const fs::path dir = makeKit("raylab", "student");
    const std::string md = readFile(dir / "report.md"), html = readFile(dir / "report.html");
    for (const auto& [lab, figure] : courseFigures()) {
        const std::string& id = figure->id;
        CHECK_MESSAGE(md.find(id) != std::string::npos, id);
        CHECK_MESSAGE(!fs::exists(dir / "figures" / (id + ".png")), id);
        CHECK_MESSAGE(md.find("FAIL  lab" + std::to_string(lab->number) + "  figure " + id + ":") != std::string::npos, id);
    }
    for (const raylab::grader::LabDescription& description : courseLabs().labs) {
        const int lab = description.number;
        const std::size_t begin = md.find("## Lab " + std::to_string(lab) + ": ");
        REQUIRE(begin != std::string::npos);
        const std::string section = md.substr(begin, md.find("\n## Lab ", begin + 1) - begin);
        CHECK_MESSAGE(section.find(" not done yet: write ") != std::string::npos, section);
        // A figure drawn through lab 2's camera names its own lab's functions, and lab 2 first.
        if (std::find(description.uses.begin(), description.uses.end(), 2) != description.uses.end())
            CHECK_MESSAGE((section.find("lab " + std::to_string(lab) + ": write ") != std::string::npos &&
                           section.find("; this figure first needs lab 2: write PerspectiveCamera::updateViewport in labs/") !=
                               std::string::npos),
                          section);
        CHECK(md.find("<!-- raylab:student lab" + std::to_string(lab) + " -->") != std::string::npos);
    }
    CHECK(html.find("not done yet") != std::string::npos);
    checkImagesExist(dir, md, html);
}

TEST_CASE("a re-run keeps the student's text: in place, rendered in the HTML, escaped; what it cannot place is kept") {
    const fs::path dir = makeKit("raylab", "rerun");
    std::string md = readFile(dir / "report.md");
    const std::string placeholder = "*Write here what you did, what the figures show and what went wrong.*\n";
    const auto writeIn = [&](int lab, const std::string& text) {
        const std::string marker = "<!-- raylab:student lab" + std::to_string(lab) + " -->\n";
        const std::size_t at = md.find(marker + placeholder);
        REQUIRE(at != std::string::npos);
        md.replace(at + marker.size(), placeholder.size(), text);
    };
    // Images: one the kit rendered, and two from elsewhere, which report.html and the PDF leave out.
    const std::string figure = "figures/" + courseFigures().front().second->id + ".png";
    writeIn(2, "Lab 2: the camera *looks* down **-z**; see `generateRay`.\n\n- one\n- two\n\n![mine](" + figure +
                   ") ![leak](/etc/hostname) ![up](../../../secret.png)\n");
    writeIn(3, "<script>alert('lab 3')</script> & the sphere.\n");
    // Lab 3's section moved to the top of the file.
    const std::size_t lab3 = md.find("<!-- raylab:student lab3 -->");
    const std::size_t lab3End = md.find("<!-- raylab:end -->", lab3) + std::strlen("<!-- raylab:end -->\n");
    const std::string moved = md.substr(lab3, lab3End - lab3);
    md.erase(lab3, lab3End - lab3);
    md = moved + md;
    md += "\nA conclusion written after every marker.\n";
    write(dir / "report.md", md);

    runKit("raylab", dir);
    const std::string again = readFile(dir / "report.md"), html = readFile(dir / "report.html");
    CHECK(again.find("<!-- raylab:student lab2 -->\nLab 2: the camera *looks* down **-z**") != std::string::npos);
    CHECK(again.find("&amp; the sphere.") == std::string::npos);
    CHECK(again.find("the sphere.") > again.find("## Lab 3: ")); // back under lab 3
    CHECK(again.find("the sphere.") < again.find("## Lab 4: "));
    CHECK(again.find("## Kept from the previous version") != std::string::npos);
    CHECK(again.find("A conclusion written after every marker.") > again.find("<!-- raylab:student kept -->"));
    CHECK(readFile(dir / "report.previous.md") == md);
    // The console says what moved, from where, and to which section of which file.
    const std::string output = readFile(dir / "output.txt");
    const std::string file = (dir / "report.md").string();
    const auto conclusion = std::count(md.begin(), md.begin() + std::ptrdiff_t(md.find("A conclusion")), '\n') + 1;
    CHECK_MESSAGE(output.find(file + ": 1 piece of your text moved to the section \"Kept from the previous version\" at its end") !=
                      std::string::npos, output);
    CHECK_MESSAGE(output.find(file + ":" + std::to_string(conclusion) + ": text outside the raylab:student markers\n") !=
                      std::string::npos, output);
    // The HTML shows the student's Markdown, as HTML, and their markup as text.
    CHECK(html.find("the camera <em>looks</em> down <strong>-z</strong>; see <code>generateRay</code>") != std::string::npos);
    CHECK(html.find("<li>one</li>") != std::string::npos);
    CHECK(html.find("<script>alert") == std::string::npos);
    CHECK(html.find("A conclusion written after every marker.") != std::string::npos);
    CHECK(html.find("<img src=\"" + figure + "\" alt=\"mine\"") != std::string::npos);
    for (const std::string address : {"/etc/hostname", "../../../secret.png"}) {
        CHECK_MESSAGE(html.find("src=\"" + address) == std::string::npos, address);
        CHECK_MESSAGE(html.find("[image left out: " + address + "]") != std::string::npos, address);
        CHECK_MESSAGE(output.find(file + ": the image " + address + " is left out of report.html and the PDF") != std::string::npos,
                      output);
    }
}

TEST_CASE("the title block comes from report.toml: created with placeholders, then the student's; errors name the line and key") {
    const fs::path dir = makeKit("raylab", "title");
    CHECK(readFile(dir / "report.toml").find("name = \"Your name\"") != std::string::npos);
    CHECK(readFile(dir / "output.txt").find("note: fill in") != std::string::npos);
    write(dir / "report.toml", "name = \"Ada Lovelace\"\ngroup = \"B2\"\ncourse = \"Rendering 101\"\ndate = \"2026-11-23\"\n");
    runKit("raylab", dir);
    const std::string md = readFile(dir / "report.md");
    CHECK(md.find("- **Name**: Ada Lovelace\n- **Group**: B2\n- **Course**: Rendering 101\n- **Date**: 2026\\-11\\-23\n") !=
          std::string::npos);
    CHECK(readFile(dir / "report.html").find("Ada Lovelace") != std::string::npos);
    CHECK(readFile(dir / "output.txt").find("note: fill in") == std::string::npos);

    write(dir / "report.toml", "name = \"Ada Lovelace\"\ngroup = 2\n");
    CHECK(run({program("raylab"), "report", "--out", dir.string()}, dir) != 0);
    const std::string error = readFile(dir / "output.txt");
    CHECK_MESSAGE(error.find("report.toml:2: group: must be a string") != std::string::npos, error);
    CHECK(run({program("raylab"), "report", "--lang", "fr", "--out", dir.string()}, dir) != 0);
    const std::string french = readFile(dir / "output.txt");
    CHECK_MESSAGE(french.find("report.toml:2: group\u00A0: doit être une chaîne entre guillemets") != std::string::npos, french);
}

TEST_CASE("--pdf without chromium: a clear message, no PDF") {
    const fs::path dir = kitFolder("pdf");
    const char* path = std::getenv("PATH");
    const std::string ourPath = path ? path : "";
    setenv("PATH", "/nonexistent", 1); // raylab finds no chromium
    const int status = run({program("raylab"), "report", "--threads", "2", "--pdf", "--out", dir.string()}, dir);
    setenv("PATH", ourPath.c_str(), 1);
    CHECK(status == 1);
    CHECK(readFile(dir / "output.txt").find("--pdf prints with chromium, which is not installed (install it with ") !=
          std::string::npos);
    CHECK(!fs::exists(dir / "report.pdf"));
}


TEST_CASE("--lang fr: French headings, grade lines and typography") {
    const fs::path dir = makeKit("raylab-reference", "french", {"--lang", "fr"});
    const std::string md = readFile(dir / "report.md");
    CHECK(md.find("# Compte rendu de TP") != std::string::npos);
    CHECK(md.find("## TP 3\u00A0: Une sphère") != std::string::npos);
    CHECK(md.find("### Votre texte (TP 2)") != std::string::npos);
    CHECK(md.find("Figure 3(c) (lab3_cosine)") != std::string::npos);
    CHECK(std::regex_search(md, std::regex("temps de rendu\u00A0: [0-9]+,[0-9]{3} s")));
    CHECK(md.find("- **Nom**\u00A0: Votre nom") != std::string::npos);
    CHECK(md.find("sombre\u00A0: dans la tolérance") != std::string::npos);
    // The grade block says the grader's lines in French too.
    CHECK(md.find("RÉUSSI  TP 1  test fillGradient\u00A0: les coins et le milieu") != std::string::npos);
    CHECK(md.find("TP 1\u00A0: 10 / 10 (") != std::string::npos);
    CHECK(md.find("PASS  lab") == std::string::npos);
    // What the command prints is French too.
    const std::string output = readFile(dir / "output.txt");
    CHECK_MESSAGE(output.find("raylab report, version de référence (") != std::string::npos, output);
    CHECK_MESSAGE(output.find(" build (") == std::string::npos, output);
    CHECK_MESSAGE(output.find("compte rendu\u00A0: " + (dir / "report.md").string() + " et ") != std::string::npos, output);
    CHECK_MESSAGE(output.find("report: ") == std::string::npos, output);
}

}

// Its own suite: skipped without chromium (support/needs.h).
TEST_SUITE("report: lab 5") { // the reference kit the suite "report" made; skipped in a course without lab 5

TEST_CASE("the antialiasing section: both renders' cost, the close-up's place and zoom; the noisy figure's reading") {
    if (!raylab::test::labInCourse(RAYLAB_LABS_DIR, 5)) return;
    const std::string md = readFile(fs::path(RAYLAB_REPORT_TEST_DIR) / "reference" / "report.md");
    CHECK(md.find("A noisy figure: a pixel is within tolerance") != std::string::npos);
    CHECK(md.find("Antialiasing: aliased against antialiased") != std::string::npos);
    CHECK(md.find("zoom/lab3_cosine.png") != std::string::npos);
    CHECK(md.find("zoom/lab5_antialiased.png") != std::string::npos);
    CHECK(std::regex_search(md, std::regex(R"(aliased \(figure 3\(c\)\): 1 sample per pixel, [0-9]+ rays, [0-9.]+ s)")));
    CHECK(std::regex_search(md, std::regex(R"(antialiased \(figure 6\): [0-9]+ samples per pixel, [0-9]+ rays, [0-9.]+ s)")));
    CHECK(std::regex_search(md, std::regex(R"(Close-up: pixels x [0-9]+ to [0-9]+, y [0-9]+ to [0-9]+ of the [0-9]+ x [0-9]+ picture, each enlarged 10 times)")));
}

TEST_CASE("the difference map of a passing noisy render (lab 5) is dark: within tolerance") {
    if (!raylab::test::labInCourse(RAYLAB_LABS_DIR, 5)) return;
    const fs::path dir = fs::path(RAYLAB_REPORT_TEST_DIR) / "reference";
    REQUIRE(fs::exists(dir / "diff" / "lab5_antialiased.png"));
    const raylab::Image8 map = raylab::readImage(dir / "diff" / "lab5_antialiased.png");
    std::size_t dark = 0;
    for (int j = 0; j < map.height; ++j)
        for (int i = 0; i < map.width; ++i) {
            const std::uint8_t* p = map.pixel(i, j);
            if (p[0] == p[1] && p[1] == p[2] && p[0] <= 40) ++dark;
        }
    CHECK(double(dark) >= 0.999 * double(map.width) * double(map.height));
}

} // TEST_SUITE

TEST_SUITE("report pdf") {

TEST_CASE("--pdf: a PDF with chromium") {
    if (raylab::test::neededProgram("chromium", "chromium").empty()) return;
    const fs::path dir = kitFolder("pdf-printed");
    runKit("raylab", dir, {"--pdf"});
    CHECK(readFile(dir / "report.pdf").rfind("%PDF", 0) == 0);
    CHECK(fs::file_size(dir / "report.pdf") > 10000);
}

} // TEST_SUITE
