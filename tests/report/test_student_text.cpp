// report.md is the student's: a re-run places each of their sections by its marker, never by
// position, and keeps what it cannot place. These run on the text alone (no render).
#include <doctest/doctest.h>

#include "report/student_text.h"

#include <algorithm>
#include <string>
#include <vector>

using namespace raylab::report;

namespace {

const std::string kEnglish = "en"; // a named string: no temporary for the reference to outlive
const Words& kWords = wordsFor(kEnglish);

// A document as a run writes it: two labs, each a generated part and the student's section.
std::vector<Segment> freshDocument() {
    return {{Segment::Kind::Generated, "title", "# Lab report\n"},
            {Segment::Kind::Generated, "lab1", "## Lab 1\n\nrender time: 0.001 s\n"},
            {Segment::Kind::Student, "lab1", "*Write here.*\n"},
            {Segment::Kind::Generated, "lab2", "## Lab 2\n\nrender time: 0.002 s\n"},
            {Segment::Kind::Student, "lab2", "*Write here.*\n"}};
}

std::string rerun(const std::string& previous) {
    return toMarkdown(placeStudentText(freshDocument(), readPreviousText(previous, kWords), kWords));
}

// The student's section KEY in a report.md, or "(none)".
std::string section(const std::string& markdown, const std::string& key) {
    const std::string begin = "<!-- raylab:student " + key + " -->\n";
    const std::size_t at = markdown.find(begin);
    if (at == std::string::npos) return "(none)";
    const std::size_t start = at + begin.size();
    return markdown.substr(start, markdown.find("<!-- raylab:end -->", start) - start);
}

void replace(std::string& text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    REQUIRE_MESSAGE(at != std::string::npos, from);
    text.replace(at, from.size(), to);
}

} // namespace

TEST_SUITE("report") {

TEST_CASE("student text: a first run writes the placeholders and no kept section") {
    const std::string md = rerun("");
    CHECK(section(md, "lab1") == "*Write here.*\n");
    CHECK(section(md, "lab2") == "*Write here.*\n");
    CHECK(section(md, kKeptKey) == "(none)");
    CHECK(rerun(md) == md); // nothing written: nothing changes
}

TEST_CASE("student text: each section stays under its marker, even when the student moved it") {
    std::string md = rerun("");
    replace(md, "<!-- raylab:student lab1 -->\n*Write here.*\n", "<!-- raylab:student lab1 -->\nMy **first** lab.\n\nTwo paragraphs.\n");
    replace(md, "<!-- raylab:student lab2 -->\n*Write here.*\n", "<!-- raylab:student lab2 -->\nThe second.\n");
    // Moved: lab 2's section cut and pasted before lab 1's generated part.
    const std::string lab2 = "<!-- raylab:student lab2 -->\nThe second.\n<!-- raylab:end -->\n";
    replace(md, lab2, "");
    replace(md, "<!-- raylab:generated lab1", lab2 + "<!-- raylab:generated lab1");
    const std::string again = rerun(md);
    CHECK(section(again, "lab1") == "My **first** lab.\n\nTwo paragraphs.\n");
    CHECK(section(again, "lab2") == "The second.\n");
    CHECK(again.find("The second.") > again.find("## Lab 2")); // back in its place
    CHECK(section(again, kKeptKey) == "(none)");
}

TEST_CASE("student text: text outside the markers, a deleted marker and an unknown section are kept") {
    std::string md = rerun("");
    replace(md, "<!-- raylab:student lab1 -->\n*Write here.*\n<!-- raylab:end -->",
            "<!-- raylab:student lab1 -->\nLab 1 text whose end marker was deleted.\n");
    replace(md, "<!-- raylab:student lab2 -->\n*Write here.*\n", "Lab 2 text whose begin marker was deleted.\n");
    md += "A paragraph written after the last marker.\n";
    md += "<!-- raylab:student lab9 -->\nA lab that is gone.\n<!-- raylab:end -->\n";
    const std::string again = rerun(md);
    CHECK(section(again, "lab1") == "Lab 1 text whose end marker was deleted.\n");
    CHECK(section(again, "lab2") == "*Write here.*\n");
    const std::string kept = section(again, kKeptKey);
    CHECK(kept.find("Lab 2 text whose begin marker was deleted.") != std::string::npos);
    CHECK(kept.find("A paragraph written after the last marker.") != std::string::npos);
    CHECK(kept.find("From the section `lab9`:\n\nA lab that is gone.") != std::string::npos);
    CHECK(again.find("## Kept from the previous version") != std::string::npos);
    // A third run keeps the kept section as it is, each text once.
    const std::string third = rerun(again);
    CHECK(section(third, kKeptKey) == kept);
}

TEST_CASE("student text: an edit inside a generated part is kept; CRLF line ends are no edit") {
    std::string md = rerun("");
    std::string crlf;
    for (char c : md) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    CHECK(section(rerun(crlf), kKeptKey) == "(none)");
    replace(md, "render time: 0.001 s\n", "render time: 0.001 s\n\nA remark under the figure.\n");
    const std::string kept = section(rerun(md), kKeptKey);
    CHECK(kept.find("Your edit of the generated part `lab1`") != std::string::npos);
    CHECK(kept.find("A remark under the figure.") != std::string::npos);
}

TEST_CASE("student text: what moves to the kept section is told, with its line and section, in the report's language") {
    std::string md = rerun("");
    md += "<!-- raylab:student lab9 -->\nA lab that is gone.\n<!-- raylab:end -->\n";
    replace(md, "render time: 0.002 s\n", "render time: 0.002 s\nMy remark.\n");
    md += "\nA last paragraph.\n";
    const auto lineOf = [&](const std::string& text) {
        return std::to_string(std::count(md.begin(), md.begin() + std::ptrdiff_t(md.find(text)), '\n') + 1);
    };
    std::vector<UnplacedText> moved;
    const std::string again = toMarkdown(placeStudentText(freshDocument(), readPreviousText(md, kWords), kWords, &moved));
    REQUIRE(moved.size() == 3);
    const std::string notice = movedTextNotice(moved, "out/report.md", kWords);
    CHECK_MESSAGE(notice.find("out/report.md: 3 pieces of your text moved to the section \"Kept from the previous version\"") == 0,
                  notice);
    CHECK_MESSAGE(notice.find("move them where they belong:\n") != std::string::npos, notice);
    CHECK_MESSAGE(notice.find("  out/report.md:" + lineOf("<!-- raylab:student lab9") + ": your section `lab9`, which the report no longer has\n") !=
                      std::string::npos, notice);
    CHECK_MESSAGE(notice.find("  out/report.md:" + lineOf("<!-- raylab:generated lab2") + ": your edit inside the generated part `lab2`\n") !=
                      std::string::npos, notice);
    CHECK_MESSAGE(notice.find("  out/report.md:" + lineOf("A last paragraph") + ": text outside the raylab:student markers\n") !=
                      std::string::npos, notice);
    const std::string french = movedTextNotice(moved, "out/report.md", wordsFor("fr"));
    CHECK_MESSAGE(french.find("3 morceaux de votre texte déplacés dans la section «\u00A0Conservé de la version précédente\u00A0»") !=
                      std::string::npos, french);
    CHECK_MESSAGE(french.find("out/report.md:" + lineOf("A last paragraph") + "\u00A0: du texte hors des marqueurs") !=
                      std::string::npos, french);
    // A second run moves nothing more: the kept section is the student's now; nothing to tell.
    std::vector<UnplacedText> movedAgain;
    placeStudentText(freshDocument(), readPreviousText(again, kWords), kWords, &movedAgain);
    CHECK(movedAgain.empty());
    CHECK(movedTextNotice(movedAgain, "out/report.md", kWords).empty());
    // One piece: singular.
    const std::vector<UnplacedText> one(moved.begin(), moved.begin() + 1);
    CHECK(movedTextNotice(one, "r.md", kWords).find("r.md: 1 piece of your text moved") == 0);
}

}
