// raylab report, as a student runs it: the reference build's kit has every figure, its handout
// number, the pictures it shows and an empty section per lab; the student build (stubs) reports
// each lab as not done yet.
#include "support/run_program.h"

#include <doctest/doctest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const char* const kFigures[][2] = {
    {"lab1_gradient", "Figure 1 "},     {"lab2_directions", "Figure 2 "}, {"lab3_flat", "Figure 3(a)"},
    {"lab3_placeholder_normal", "Figure 3(b)"}, {"lab3_cosine", "Figure 3(c)"}, {"lab4_a", "Figure 5(a)"},
    {"lab4_b", "Figure 5(b)"},          {"lab4_c", "Figure 5(c)"},        {"lab4_d", "Figure 5(d)"},
    {"lab5_antialiased", "Figure 6 "},
};

std::string read(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// Runs `PROGRAM report --out DIR ARGS` (the kit is also where the browser test looks).
fs::path makeKit(const char* program, const std::string& name, const std::vector<std::string>& args = {}) {
    const fs::path dir = fs::path(RAYLAB_REPORT_TEST_DIR) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::vector<std::string> argv{(fs::path(RAYLAB_BIN_DIR) / program).string(), "report", "--threads", "2", "--out", dir.string()};
    argv.insert(argv.end(), args.begin(), args.end());
    const raylab::test::ProgramRun run = raylab::test::runProgram(argv, dir / "output.txt");
    REQUIRE_MESSAGE(run.status == 0, run.output);
    REQUIRE(fs::exists(dir / "report.md"));
    REQUIRE(fs::exists(dir / "report.html"));
    return dir;
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
    CHECK(!htmlImages.empty());
    for (const std::vector<std::string>* list : {&mdImages, &htmlImages})
        for (const std::string& src : *list) {
            CHECK_MESSAGE(fs::is_regular_file(dir / src), src);
            CHECK_MESSAGE(src.find("://") == std::string::npos, src); // standalone: nothing from a network
            CHECK_MESSAGE(!fs::path(src).is_absolute(), src);
        }
}

} // namespace

TEST_SUITE("report") {

TEST_CASE("the reference build's kit: every figure, its number, its pictures, an empty section per lab") {
    const fs::path dir = makeKit("raylab-reference", "reference");
    const std::string md = read(dir / "report.md"), html = read(dir / "report.html");
    for (const auto& [id, number] : kFigures) {
        CHECK_MESSAGE(md.find(id) != std::string::npos, id);
        CHECK_MESSAGE(html.find(id) != std::string::npos, id);
        CHECK_MESSAGE(md.find(std::string(number) + (number[std::strlen(number) - 1] == ' ' ? "(" : " (") + id + ")") !=
                          std::string::npos,
                      number << " " << id);
        CHECK_MESSAGE(md.find("figures/" + std::string(id) + ".png") != std::string::npos, id);
        CHECK_MESSAGE(md.find("grade/images/" + std::string(id) + ".diff.png") != std::string::npos, id);
        CHECK_MESSAGE(html.find("grade/images/" + std::string(id) + ".reference.png") != std::string::npos, id);
        CHECK_MESSAGE(md.find("PASS  lab" + std::string(1, id[3]) + "  figure " + id + ":") != std::string::npos, id);
    }
    for (int lab = 1; lab <= 5; ++lab) {
        CHECK(md.find("## Lab " + std::to_string(lab) + ": ") != std::string::npos);
        CHECK(md.find("### Your text (Lab " + std::to_string(lab) + ")\n\n<!-- raylab:your-text lab=" +
                      std::to_string(lab) + " -->") != std::string::npos);
        CHECK(html.find("id=\"your-text-lab" + std::to_string(lab) + "\"") != std::string::npos);
    }
    CHECK(md.find("Antialiasing: aliased against antialiased") != std::string::npos);
    CHECK(md.find("zoom/lab3_cosine.png") != std::string::npos);
    CHECK(md.find("zoom/lab5_antialiased.png") != std::string::npos);
    CHECK(md.find("render time: ") != std::string::npos);
    CHECK(md.find("not done yet") == std::string::npos);
    CHECK(html.find("<pre id=\"image-check\" hidden>image check: not run</pre>") != std::string::npos);
    checkImagesExist(dir, md, html);
}

TEST_CASE("the student build's kit (stubs): each lab not done yet, the references still shown") {
    const fs::path dir = makeKit("raylab", "student");
    const std::string md = read(dir / "report.md"), html = read(dir / "report.html");
    for (const auto& [id, number] : kFigures) {
        CHECK_MESSAGE(md.find(id) != std::string::npos, id);
        CHECK_MESSAGE(!fs::exists(dir / "figures" / (std::string(id) + ".png")), id);
        CHECK_MESSAGE(md.find("FAIL  lab" + std::string(1, id[3]) + "  figure " + id + ": missing") != std::string::npos, id);
    }
    for (int lab = 1; lab <= 5; ++lab) {
        const std::size_t begin = md.find("## Lab " + std::to_string(lab) + ": ");
        REQUIRE(begin != std::string::npos);
        const std::string section = md.substr(begin, md.find("\n## Lab ", begin + 1) - begin);
        CHECK_MESSAGE(section.find(" not done yet: write ") != std::string::npos, section);
        CHECK(md.find("<!-- raylab:your-text lab=" + std::to_string(lab) + " -->") != std::string::npos);
    }
    CHECK(html.find("not done yet") != std::string::npos);
    checkImagesExist(dir, md, html);
}

TEST_CASE("--lang fr: French headings") {
    const fs::path dir = makeKit("raylab-reference", "french", {"--lang", "fr"});
    const std::string md = read(dir / "report.md");
    CHECK(md.find("# Compte rendu de TP") != std::string::npos);
    CHECK(md.find("## TP 3 : Une sphère") != std::string::npos);
    CHECK(md.find("### Votre texte (TP 2)") != std::string::npos);
    CHECK(md.find("Figure 3(c) (lab3_cosine)") != std::string::npos);
}

}
