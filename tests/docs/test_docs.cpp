// The docs: every relative link and image of every Markdown file resolves; the handouts' figures
// agree with the labs' descriptions (labs/<lab>/lab.toml) and live in their labs' folders; the contact sheet.
#include "link_check.h"
#include "support/scene_files.h"

#include "grader/lab_catalog.h"

#include "raylab/image_io.h"
#include "src/contact_sheet.h"
#include "src/scene_file.h"

#include <doctest/doctest.h>

#include <fstream>
#include <map>
#include <random>
#include <regex>
#include <set>
#include <sstream>

namespace fs = std::filesystem;
using namespace raylab;
using namespace raylab::test;

namespace {

const fs::path kRoot = RAYLAB_SOURCE_DIR;

// tests/docs/pending_links.txt: targets that another branch adds, accepted while missing.
std::set<fs::path> pendingLinks() {
    std::set<fs::path> pending;
    std::ifstream in(kRoot / "tests/docs/pending_links.txt");
    std::string line;
    while (std::getline(in, line)) {
        line = line.substr(0, line.find('#'));
        std::istringstream words(line);
        std::string path;
        if (words >> path) pending.insert(fs::path(path).lexically_normal());
    }
    return pending;
}

// The files `raylab distribute` writes at the top of the students' tree, where the handouts are read:
// a link there resolves in that tree (framework/cli/students_readme.cpp; the test "distribute readme"
// checks their own links). The French handouts link LISEZMOI.md, the students' French README.
const std::set<fs::path> kWrittenByDistribute{"LISEZMOI.md"};

std::string readFile(const fs::path& file) {
    std::ifstream in(file);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Every "Figure <number>: `<id>`" of a Markdown file (French puts a space, often a no-break one,
// before the colon), as id -> numbers.
std::multimap<std::string, std::string> figureMentions(const std::string& text) {
    static const std::regex mention("Figure ([0-9]+(\\([a-z]\\))?)(?: |\u00a0|\u202f)?: `([a-z0-9_]+)`");
    std::multimap<std::string, std::string> found;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), mention); it != std::sregex_iterator(); ++it)
        found.emplace((*it)[3].str(), (*it)[1].str());
    return found;
}

} // namespace

TEST_SUITE("figure tables") {
    TEST_CASE("each handout numbers its lab's figures and names its files as its lab.toml does") {
        const auto catalog = raylab::grader::loadLabCatalog(kRoot / "labs");
        for (const auto& lab : catalog.labs)
            for (const char* handout : {"README.md", "README.fr.md"}) {
                const fs::path file = kRoot / "labs" / lab.id / handout;
                CAPTURE(file);
                const std::string text = readFile(file);
                const std::multimap<std::string, std::string> mentions = figureMentions(text);
                for (const auto& f : lab.figures)
                    CHECK_MESSAGE(mentions.count(f.id) >= 1, "no \"Figure " << f.handout << ": `" << f.id << "`\"");
                for (const auto& f : lab.functions) {
                    const std::string path = "`labs/" + lab.id + "/" + f.file + "`";
                    CHECK_MESSAGE(text.find(path) != std::string::npos, "the table of what to write has no " << path);
                }
                for (const auto& [id, number] : mentions) {
                    const auto* figure = catalog.figure(id);
                    CHECK_MESSAGE(figure != nullptr, id << " is the figure of no lab.toml");
                    if (figure != nullptr) CHECK_MESSAGE(number == figure->handout, id << " is Figure " << figure->handout << " in its lab.toml, not " << number);
                }
            }
    }

    TEST_CASE("each figure is a picture of its scene's size in its lab's figures/, shown by both handouts") {
        const auto catalog = raylab::grader::loadLabCatalog(kRoot / "labs");
        for (const auto& lab : catalog.labs) {
            const fs::path folder = kRoot / "labs" / lab.id / "figures";
            std::set<std::string> figures;
            for (const auto& f : lab.figures) {
                CAPTURE(f.id);
                figures.insert(f.id + ".png");
                const fs::path picture = folder / (f.id + ".png");
                if (!fs::is_regular_file(picture)) {
                    FAIL_CHECK(picture << " is missing: raylab-reference figures --handouts");
                    continue;
                }
                const Image8 image = readImage(picture);
                const SceneDescription scene = loadSceneFile(figureSceneFile(f.id));
                CHECK(image.width == scene.width);
                CHECK(image.height == scene.height);
                for (const char* handout : {"README.md", "README.fr.md"}) {
                    const std::string text = readFile(kRoot / "labs" / lab.id / handout);
                    CHECK_MESSAGE((text.find("](figures/" + f.id + ".png)") != std::string::npos ||
                                   text.find("src=\"figures/" + f.id + ".png\"") != std::string::npos),
                                  handout << " does not show figures/" << f.id << ".png");
                }
            }
            // A picture left behind by a renamed or removed figure would be shipped and never updated.
            std::error_code error;
            for (const auto& entry : fs::directory_iterator(folder, error))
                CHECK_MESSAGE(figures.count(entry.path().filename().string()) == 1,
                              entry.path() << " is no figure of " << lab.id << "'s lab.toml");
        }
    }
}

TEST_SUITE("docs links") {
    TEST_CASE("every relative link and image of every Markdown file resolves") {
        const std::vector<fs::path> files = markdownFiles(kRoot);
        REQUIRE_MESSAGE(files.size() >= 2, "found only " << files.size() << " Markdown files under " << kRoot);
        const std::set<fs::path> pending = pendingLinks();
        g_linksChecked = 0;
        std::ostringstream report;
        int broken = 0;
        for (const fs::path& file : files)
            for (const BrokenLink& b : brokenLinks(kRoot, file)) {
                if (kWrittenByDistribute.count(b.resolved) != 0) continue;
                if (pending.count(b.resolved) != 0) {
                    MESSAGE(b.file.string() << ":" << b.line << ": " << b.target
                                            << " is not there yet (accepted: tests/docs/pending_links.txt)");
                    continue;
                }
                ++broken;
                report << "\n  " << b.file.string() << ":" << b.line << ": " << b.target << " -> " << b.resolved.string()
                       << " does not exist";
            }
        CHECK_MESSAGE(broken == 0, broken << " broken links:" << report.str());
        CHECK_MESSAGE(g_linksChecked > 0, "no relative link at all: is the checker reading the files?");
    }

    TEST_CASE("pending links are still missing (else remove them from pending_links.txt)") {
        for (const fs::path& p : pendingLinks()) {
            std::error_code error;
            WARN_MESSAGE(!fs::exists(kRoot / p, error), p.string() << " exists now: remove it from tests/docs/pending_links.txt");
        }
    }

    TEST_CASE("the checker finds broken links and ignores code, URLs and anchors") {
        const fs::path dir = fs::temp_directory_path() / ("raylab_link_check_" + std::to_string(std::random_device{}()));
        fs::create_directories(dir / "sub");
        std::ofstream(dir / "sub/there.png") << "x";
        std::ofstream(dir / "sub/page.md") << "# T\n"
                                              "![ok](there.png) [ok](../top.md#part) [web](https://example.org/x.md)\n"
                                              "[anchor](#t) `[code](nowhere.md)`\n"
                                              "```\n[in a block](nowhere.md)\n```\n"
                                              "[bad](missing.md) <img src=\"gone.png\">\n"
                                              "[![pic](there.png)](../absent/index.html)\n"
                                              "[ref]: ../nope.md\n";
        std::ofstream(dir / "top.md") << "[sub](sub/page.md) [root](/sub/there.png) [space](sub/no%20such.png)\n";
        std::vector<std::string> found;
        for (const fs::path& f : markdownFiles(dir))
            for (const BrokenLink& b : brokenLinks(dir, f)) found.push_back(b.file.generic_string() + ":" + std::to_string(b.line) + ":" + b.target);
        fs::remove_all(dir);
        const std::vector<std::string> expected{"sub/page.md:7:missing.md", "sub/page.md:7:gone.png",
                                                "sub/page.md:8:../absent/index.html", "sub/page.md:9:../nope.md",
                                                "top.md:1:sub/no%20such.png"};
        CHECK(found == expected);
    }
}

TEST_SUITE("contact sheet") {
    TEST_CASE("thumbnails in order, a tile for a figure not rendered, ids written under them") {
        Image8 red{60, 40, {}};
        red.rgb.resize(60 * 40 * 3);
        for (std::size_t k = 0; k < red.rgb.size(); k += 3) red.rgb[k] = 255;
        ContactSheetLayout layout;
        layout.columns = 2;
        layout.thumbWidth = 30;
        layout.thumbHeight = 20;
        layout.margin = 4;
        const Image8 sheet = makeContactSheet({{"a1", red, ""}, {"b_2", std::nullopt, "todo"}, {"c", red, ""}}, layout);
        const int labelHeight = 20;
        CHECK(sheet.width == 4 + 2 * (30 + 4));
        CHECK(sheet.height == 4 + 2 * (20 + labelHeight + 4));
        const auto is = [&](int x, int y, int r, int g, int b) {
            const std::uint8_t* p = sheet.pixel(x, y);
            return p[0] == r && p[1] == g && p[2] == b;
        };
        CHECK(is(4 + 15, 4 + 10, 255, 0, 0));              // first thumbnail, shrunk by 2
        CHECK(is(4 + 34 + 1, 4 + 1, 64, 64, 64));          // second: the "todo" tile
        CHECK(is(4 + 15, 4 + 20 + labelHeight + 4 + 10, 255, 0, 0)); // third, on the second row
        int ink = 0;                                          // the first id, under its thumbnail
        for (int y = 4 + 20; y < 4 + 20 + labelHeight; ++y)
            for (int x = 4; x < 4 + 30; ++x) ink += is(x, y, 0, 0, 0) ? 1 : 0;
        CHECK(ink > 10);
        CHECK(contactSheetTextWidth("lab3_placeholder_normal", 2) <= 280);
    }
}
