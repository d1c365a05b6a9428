// Issue 42: every grade on its student's row, whatever the student's folder is called. A class of
// folder names of every awkward kind (both slashes, a newline, a tab, control bytes, bytes that are
// not UTF-8, Latin-1, bidi controls and other invisible characters, 255 bytes, a formula, ';' and
// ',' inside), half of it graded by the reference and half by the course's first lab left undone,
// into one OUT: grades.csv, both gradebook files (without a roster, then with one that names some of
// them, byte for byte), the class page and the console each give every student their own grade,
// show their name visibly and once, and name the rows that match nothing. The CSV files read the
// same in Python's csv with ',' and with ';' (no cell a formula either way), and in LibreOffice
// where it is installed. The students are graded by prebuilt agents (--agent): nothing is compiled.
#include "grader/class_page/class_page.h"
#include "grader/class_page/gradebook.h"
#include "grader/class_page/similarity.h"
#include "grader/course/class_run.h"
#include "grader/judge/diagnosis.h"
#include "grader/lab_catalog.h"
#include "grading_support.h"
#include "src/markup.h"
#include "src/text.h"
#include "support/files.h"
#include "support/needs.h"
#include "support/read_csv.h"
#include "support/run_program.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <string>
#include <vector>

using namespace raylab::test;

namespace doctest {
template <> struct StringMaker<std::vector<std::string>> {
    static String convert(const std::vector<std::string>& cells) {
        std::string shown = "{";
        for (const std::string& c : cells) shown += (shown.size() > 1 ? ", \"" : "\"") + raylab::printableName(c) + "\"";
        return (shown + "}").c_str();
    }
};
} // namespace doctest

namespace {

struct Name {
    std::string folder;  // its bytes
    std::string shown;   // as the console, grades.csv and the page show it
    std::string inCsv;   // as a CSV reader reads its cell back, when not `shown` (a formula defused)
    bool solved = false; // graded by the reference (else by the first lab's stub)
    const std::string& cell() const { return inCsv.empty() ? shown : inCsv; }
};

std::string repeated(const std::string& part, int times) {
    std::string whole;
    for (int k = 0; k < times; ++k) whole += part;
    return whole;
}

// Each next to one it would print like if a name were made printable twice (a\b and a\\b: the first
// shows as the second's bytes), the two graded differently.
const std::vector<Name>& names() {
    static const std::vector<Name> all{
        {"a\\b", "a\\\\b", "", true},
        {"a\\\\b", "a\\\\\\\\b", "", false},
        {"H\xE9lo\xEFse;=1+1;", "H\\xE9lo\\xEFse;=1+1;", "H\\xE9lo\\xEFse;'=1+1;", true},
        {"new\nline", "new\\nline", "", true},
        {"new\\nline", "new\\\\nline", "", false},
        {"tab\there", "tab\\there", "", true},
        {"tab\\there", "tab\\\\there", "", false},
        {"ctl\x01\x1B[2J\x7F\xC2\x85", "ctl\\x01\\x1B[2J\\x7F\\xC2\\x85", "", true},
        {"bad\xFF\xC3(utf8\xED\xA0\x80", "bad\\xFF\\xC3(utf8\\xED\\xA0\\x80", "", false},
        {"\xE2\x80\xAEgnissim", "\\xE2\\x80\\xAEgnissim", "", true},
        {"iso\xE2\x81\xA6late\xE2\x81\xA9 lrm\xE2\x80\x8E rlm\xE2\x80\x8F alm\xD8\x9C zw\xE2\x80\x8B\xE2\x80\x8D\xEF\xBB\xBF",
         "iso\\xE2\\x81\\xA6late\\xE2\\x81\\xA9 lrm\\xE2\\x80\\x8E rlm\\xE2\\x80\\x8F alm\\xD8\\x9C zw\\xE2\\x80\\x8B\\xE2\\x80\\x8D"
         "\\xEF\\xBB\\xBF",
         "", false},
        {"z" + repeated("\xC3\xA9", 127), "z" + repeated("\xC3\xA9", 127), "", true}, // 255 bytes of UTF-8
        {repeated("\xE9", 255), repeated("\\xE9", 255), "", false},                  // 255 of Latin-1
        {"=1+1", "=1+1", "'=1+1", true},
        {"+1+1", "+1+1", "'+1+1", false},
        {"-x", "-x", "'-x", true},
        {"@SUM(1)", "@SUM(1)", "'@SUM(1)", false},
        {"semi;colon,comma", "semi;colon,comma", "", true},
        {"x,=2+2;-3+3\n@A1", "x,=2+2;-3+3\\n@A1", "x,'=2+2;'-3+3\\n@A1", false},
    };
    return all;
}

// The course's first lab: the one graded.
const raylab::grader::LabDescription& firstLab() {
    static const raylab::grader::LabDescription lab = raylab::grader::loadLabCatalog(sourceDir() / "labs").labs.at(0);
    return lab;
}

struct GradedClass {
    fs::path root, out;
    std::string output; // both runs' console
};

std::string sandboxShown() {
    const char* sandbox = std::getenv("RAYLAB_SANDBOX");
    return sandbox ? sandbox : "";
}

// grade-class of the solved names with the reference's agent, then of the others with the first lab's
// stub, into one OUT: the agent given by one path, the program behind it changed between the runs,
// so that the second run keeps the first's results (made alike) in grades.csv.
const GradedClass& gradedClass() {
    static const GradedClass graded = [] {
        GradedClass g;
        g.root = freshFolder("raylab-class-names" + sandboxShown());
        g.out = g.root / "out";
        const std::string stub = "raylab-nothing-lab" + std::to_string(firstLab().number);
        for (const bool solved : {false, true}) {
            const fs::path agent = binDir() / (solved ? "raylab-agent-reference" : stub);
            REQUIRE_MESSAGE(fs::exists(agent), agent << " is not built");
            fs::copy_file(agent, g.root / "agent", fs::copy_options::overwrite_existing);
            const fs::path classDir = g.root / (solved ? "solved" : "stubs");
            for (const Name& n : names())
                if (n.solved == solved) {
                    fs::create_directories(classDir / n.folder / firstLab().id);
                    std::ofstream(classDir / n.folder / firstLab().id / firstLab().files().at(0)) << "// a student\n";
                }
            std::vector<std::string> args{(binDir() / "raylab").string(), "grade-class", classDir.string(), "--out",
                                          g.out.string(), "--agent", (g.root / "agent").string(), "--lab",
                                          std::to_string(firstLab().number), "--threads", "2", "--timeout", "60",
                                          "--lang", "en"};
            if (sandboxShown().empty() && !bubblewrapMissing().empty()) args.push_back("--no-sandbox");
            const ProgramRun run = runProgram(args, g.root / (solved ? "output-solved.txt" : "output-stubs.txt"));
            REQUIRE_MESSAGE(run.status == 0, run.output);
            g.output += run.output;
        }
        return g;
    }();
    return graded;
}

// The first character that would show as nothing or reorder the text, or a control character but
// for those `allowed`: what precedes it, made printable; empty when there is none.
std::string unseen(const std::string& text, const std::string& allowed = "\n") {
    static const std::vector<std::string> invisible{
        "\xE2\x80\xAA", "\xE2\x80\xAB", "\xE2\x80\xAC", "\xE2\x80\xAD", "\xE2\x80\xAE", "\xE2\x81\xA6", "\xE2\x81\xA7",
        "\xE2\x81\xA8", "\xE2\x81\xA9", "\xE2\x80\x8E", "\xE2\x80\x8F", "\xD8\x9C", "\xE2\x80\x8B", "\xE2\x80\x8D", "\xEF\xBB\xBF"};
    for (std::size_t k = 0; k < text.size(); ++k) {
        const auto byte = static_cast<unsigned char>(text[k]);
        bool found = ((byte < 0x20 || byte == 0x7F) && allowed.find(text[k]) == std::string::npos) ||
                     (byte == 0xC2 && k + 1 < text.size() && static_cast<unsigned char>(text[k + 1]) <= 0x9F);
        for (const std::string& c : invisible) found = found || text.compare(k, c.size(), c) == 0;
        if (found) return raylab::printableName(text.substr(k < 40 ? 0 : k - 40, 44));
    }
    return "";
}

// The rows of a CSV file, each by its cell in column `key`; every row as wide as the header.
std::map<std::string, std::vector<std::vector<std::string>>> rowsBy(const fs::path& file, std::size_t key) {
    const auto rows = readCsv(readFile(file));
    REQUIRE(!rows.empty());
    std::map<std::string, std::vector<std::vector<std::string>>> by;
    for (std::size_t r = 1; r < rows.size(); ++r) {
        CHECK(rows[r].size() == rows[0].size());
        if (key < rows[r].size()) by[rows[r][key]].push_back(rows[r]);
    }
    return by;
}

struct Grade {
    std::string lab, total;
};

// Each name's grade in grades.csv, its row found once by the name as shown there.
std::map<std::string, Grade> gradesCsv(const fs::path& out) {
    const auto header = readCsv(readFile(out / "grades.csv")).at(0);
    const auto column = [&](const std::string& name) {
        const auto it = std::find(header.begin(), header.end(), name);
        REQUIRE_MESSAGE(it != header.end(), name);
        return std::size_t(it - header.begin());
    };
    const std::size_t lab = column("lab" + std::to_string(firstLab().number)), total = column("total"), max = column("max");
    const auto rows = rowsBy(out / "grades.csv", 0);
    std::map<std::string, Grade> grades;
    for (const Name& n : names()) {
        CAPTURE(n.shown);
        const auto found = rows.find(n.cell());
        REQUIRE(found != rows.end());
        REQUIRE(found->second.size() == 1);
        const std::vector<std::string>& row = found->second[0];
        if (n.solved) CHECK(row[total] == row[max]);
        else CHECK(std::stod(row[total]) < std::stod(row[max]));
        grades[n.folder] = {row[lab], row[total]};
    }
    return grades;
}

// A gradebook row as the test reads it: its first three cells, then those under lab<N> and total.
std::vector<std::string> readCells(const std::vector<std::string>& header, const std::vector<std::string>& row) {
    std::vector<std::string> cells(row.begin(), row.begin() + std::min<std::size_t>(3, row.size()));
    for (const std::string& column : {"lab" + std::to_string(firstLab().number), std::string("total")}) {
        const std::size_t k = std::size_t(std::find(header.begin(), header.end(), column) - header.begin());
        cells.push_back(k < row.size() ? row[k] : "(no column " + column + ")");
    }
    return cells;
}

const Name* named(const std::string& folder) {
    for (const Name& n : names())
        if (n.folder == folder) return &n;
    return nullptr;
}

// The class page's row of a student in its every-student table: the link to their report (their
// folder, by the identity) and the total it shows; "" when not found once.
std::string pageTotal(const std::string& page, const Name& n) {
    std::string href;
    for (char c : "students/" + raylab::grader::safeStudentName(n.folder) + "/report/index.html")
        href += c == '%' ? std::string("%25") : std::string(1, c);
    const std::string cell = "<tr><td><a href=\"" + raylab::escapeMarkup(href) + "\">" + raylab::escapeMarkup(n.shown) + "</a></td>";
    const std::size_t at = page.find(cell);
    if (at == std::string::npos || page.find(cell, at + 1) != std::string::npos) return "";
    const std::size_t end = page.find("</tr>", at);
    const std::size_t last = page.rfind("<td>", end);
    return page.substr(last + 4, page.find(" / ", last) - last - 4);
}

} // namespace

TEST_SUITE("class names") {

TEST_CASE("awkward folder names: each student's grade on their own row of grades.csv, both gradebooks and the class "
          "page, their name shown once and visibly, in the console too") {
    const GradedClass& graded = gradedClass();
    CHECK_MESSAGE(unseen(graded.output).empty(), unseen(graded.output));
    for (const Name& n : names()) {
        CAPTURE(n.shown);
        CHECK(("\n" + graded.output).find("\n" + n.shown + " ") != std::string::npos);
    }
    CHECK(graded.output.find("in neither gradebook file") == std::string::npos);
    CHECK(graded.output.find("left empty") == std::string::npos);

    const std::map<std::string, Grade> grades = gradesCsv(graded.out);
    for (const char* file : {"grades.csv", "gradebook-moodle.csv", "gradebook-canvas.csv", "index.html"}) {
        CAPTURE(file);
        const std::string text = readFile(graded.out / file);
        CHECK_MESSAGE(unseen(text).empty(), unseen(text));
    }
    // Without a roster, a row per student, named by their folder in both files.
    const std::string lab = "lab" + std::to_string(firstLab().number);
    const auto moodleHeader = readCsv(readFile(graded.out / "gradebook-moodle.csv")).at(0),
               canvasHeader = readCsv(readFile(graded.out / "gradebook-canvas.csv")).at(0);
    CHECK(readCells(moodleHeader, moodleHeader) == std::vector<std::string>{"ID number", "Email address", "Full name", lab, "total"});
    CHECK(readCells(canvasHeader, canvasHeader) == std::vector<std::string>{"Name", "SID", "Email", lab, "total"});
    const auto moodle = rowsBy(graded.out / "gradebook-moodle.csv", 2), canvas = rowsBy(graded.out / "gradebook-canvas.csv", 0);
    CHECK(moodle.size() == names().size());
    CHECK(canvas.size() == names().size());
    const std::string page = readFile(graded.out / "index.html");
    for (const Name& n : names()) {
        CAPTURE(n.shown);
        const Grade& grade = grades.at(n.folder);
        REQUIRE(moodle.count(n.cell()));
        REQUIRE(moodle.at(n.cell()).size() == 1);
        CHECK(readCells(moodleHeader, moodle.at(n.cell())[0]) == std::vector<std::string>{n.cell(), "", n.cell(), grade.lab, grade.total});
        REQUIRE(canvas.count(n.cell()));
        REQUIRE(canvas.at(n.cell()).size() == 1);
        CHECK(readCells(canvasHeader, canvas.at(n.cell())[0]) == std::vector<std::string>{n.cell(), n.cell(), "", grade.lab, grade.total});
        const std::string total = pageTotal(page, n);
        REQUIRE_MESSAGE(!total.empty(), "no row of its own on the class page");
        CHECK(std::stod(total) == std::stod(grade.total));
    }
    // Every page, and every student's report, shows the names visibly.
    for (const auto& entry : fs::recursive_directory_iterator(graded.out))
        if (entry.path().extension() == ".html") {
            CAPTURE(entry.path());
            const std::string text = readFile(entry.path());
            CHECK_MESSAGE(unseen(text, "\n\t").empty(), unseen(text, "\n\t"));
        }
}

TEST_CASE("a roster joins its rows on the folder's bytes, never on a name shown alike; each field made printable "
          "and defused; the rows that match nothing named in the console and on the page") {
    const GradedClass& graded = gradedClass();
    const std::map<std::string, Grade> grades = gradesCsv(graded.out);
    const fs::path roster = graded.root / "roster.csv";
    // a\b, Héloïse's Latin-1 bytes and the tab as they are; new\\nline as grades.csv shows the folder new<LF>line (a
    // backslash and an n): that is the folder new\nline, a backslash in its name, never new<LF>line.
    std::ofstream(roster, std::ios::binary) << "folder,id,name,email\n"
                                               "a\\b,1001,Ann Back,\"x;=1+1;@SUM(2)\"\n"
                                               "a\\\\b,=1002,\"a\n=3+3\",ann@example.org\n"
                                               "tab\there,1003,\xE2\x80\xAE" "evil,t@example.org\n"
                                               "=1+1,1004,\"Lovelace, Ada\",-2+3@example.org\n"
                                               "zoe,1005,Zoe,zoe@example.org\n"
                                               "H\xE9lo\xEFse;=1+1;,1006,H\xC3\xA9lo\xC3\xAFse,h@example.org\n"
                                               "new\\nline,1007,\"Nell\tNew\",n@example.org\n";
    const ProgramRun run = runProgram({(binDir() / "raylab").string(), "class-page", graded.out.string(), "--roster",
                                       roster.string(), "--lang", "en"},
                                      graded.root / "output-roster.txt");
    REQUIRE_MESSAGE(run.status == 0, run.output);
    CHECK_MESSAGE(unseen(run.output).empty(), unseen(run.output));
    CHECK_MESSAGE(run.output.find("In the roster but not graded (1), their grades left empty: zoe\n") != std::string::npos,
                  run.output);
    const std::vector<std::string> rostered{"a\\b", "a\\\\b", "tab\there", "=1+1", "H\xE9lo\xEFse;=1+1;", "new\\nline"};
    const std::size_t unknown = names().size() - rostered.size();
    CHECK_MESSAGE(run.output.find("Graded but not in the roster (" + std::to_string(unknown) + "), so in neither gradebook file:") !=
                      std::string::npos,
                  run.output);
    const std::string page = readFile(graded.out / "index.html");
    CHECK(page.find("<p class=\"note\" id=\"roster_missing\">In the roster but not graded (1), their grades left empty: zoe</p>") !=
          std::string::npos);
    for (const Name& n : names()) {
        CAPTURE(n.shown);
        const bool listed = std::find(rostered.begin(), rostered.end(), n.folder) != rostered.end();
        CHECK((run.output.find(" " + n.shown) != std::string::npos) == !listed); // named where it matches nothing
        const std::size_t note = page.find("id=\"roster_unknown\"");
        REQUIRE(note != std::string::npos);
        const std::string unknownNote = page.substr(note, page.find("</p>", note) - note);
        CHECK((unknownNote.find(raylab::escapeMarkup(n.shown)) != std::string::npos) == !listed);
    }

    const auto grade = [&](const std::string& folder) {
        REQUIRE(named(folder));
        return grades.at(folder);
    };
    const auto moodle = readCsv(readFile(graded.out / "gradebook-moodle.csv"));
    REQUIRE(moodle.size() == 8);
    const std::vector<std::vector<std::string>> expected{
        {"1001", "x;'=1+1;'@SUM(2)", "Ann Back", grade("a\\b").lab, grade("a\\b").total},
        {"'=1002", "ann@example.org", "a\\n=3+3", grade("a\\\\b").lab, grade("a\\\\b").total},
        {"1003", "t@example.org", "\\xE2\\x80\\xAEevil", grade("tab\there").lab, grade("tab\there").total},
        {"1004", "'-2+3@example.org", "Lovelace, Ada", grade("=1+1").lab, grade("=1+1").total},
        {"1005", "zoe@example.org", "Zoe", "", ""},
        {"1006", "h@example.org", "H\xC3\xA9lo\xC3\xAFse", grade("H\xE9lo\xEFse;=1+1;").lab, grade("H\xE9lo\xEFse;=1+1;").total},
        {"1007", "n@example.org", "Nell\\tNew", grade("new\\nline").lab, grade("new\\nline").total}};
    for (std::size_t r = 0; r < expected.size(); ++r) {
        CAPTURE(r);
        CHECK(readCells(moodle[0], moodle[r + 1]) == expected[r]);
    }
    // The students graded differently from their look-alikes: a wrong join would have swapped them.
    CHECK(grade("a\\b").total != grade("a\\\\b").total);
    CHECK(grade("new\\nline").total != grade("new\nline").total);
    const auto canvas = readCsv(readFile(graded.out / "gradebook-canvas.csv"));
    REQUIRE(canvas.size() == 8);
    for (std::size_t r = 0; r < expected.size(); ++r) {
        CAPTURE(r);
        const std::vector<std::string>& e = expected[r];
        CHECK(readCells(canvas[0], canvas[r + 1]) == std::vector<std::string>{e[2], e[0], e[1], e[3], e[4]});
    }
    for (const char* file : {"gradebook-moodle.csv", "gradebook-canvas.csv"}) {
        const std::string text = readFile(graded.out / file);
        CHECK_MESSAGE(unseen(text).empty(), unseen(text));
    }
}

TEST_CASE("the class page's every table, the mistakes' who cell and a side-by-side page's title show bidi controls "
          "visibly, even from results that hold them raw (written before names were made so)") {
    const fs::path out = freshFolder("raylab-class-names-page" + sandboxShown());
    const int lab = firstLab().number;
    const std::vector<std::string> raw{"\xE2\x80\xAEgnissim", "b\xE2\x81\xA6x\xE2\x80\x8F"};
    for (const std::string& name : raw) {
        const fs::path folder = out / "students" / raylab::grader::safeStudentName(name);
        fs::create_directories(folder);
        raylab::grader::StudentOutcome outcome;
        outcome.labs = {{lab, 1., 2., true}};
        outcome.items = {{true, lab, "a_figure", false, true, {"a_mistake"}}};
        outcome.problems = {"error: \xE2\x80\xAEreversed"};
        raylab::grader::writeStudentOutcome(outcome, folder / "outcome.json");
        std::ofstream(folder / "result.json") << nlohmann::json{{"student", name}, {"cells", nlohmann::json::array()}}.dump();
    }
    const raylab::grader::ClassResults results = raylab::grader::loadClassResults(out);
    REQUIRE(results.students.size() == 2);
    std::vector<raylab::grader::Mistake> mistakes(1);
    mistakes[0].id = "a_mistake";
    mistakes[0].nameEn = mistakes[0].nameFr = "a mistake";
    mistakes[0].lab = lab;
    raylab::grader::SimilarityReport similarity;
    raylab::grader::LabSimilarity alike;
    alike.lab = lab;
    alike.students = {results.students[0].student, results.students[1].student};
    alike.texts = {"int a;\n", "int a;\n"};
    alike.leftOut = {{false}, {false}};
    alike.pairs = {{0, 1, 90, true, {{1, 1, 1, 1, 3}}}};
    alike.median = 10.;
    alike.fence = 50.;
    alike.comparedPairs = 1;
    similarity.labs.push_back(alike);
    const raylab::grader::GradebookFiles gradebook = raylab::grader::writeGradebooks(results, {}, out);
    const raylab::grader::LabCatalog catalog = raylab::grader::loadLabCatalog(sourceDir() / "labs");
    raylab::grader::writeClassPage({results, catalog, mistakes, similarity, gradebook}, out);

    const std::string page = readFile(out / "index.html"), pair = readFile(out / "similarity" / ("lab" + std::to_string(lab) + "-1.html"));
    REQUIRE(!pair.empty());
    for (const std::string* text : {&page, &pair}) CHECK_MESSAGE(unseen(*text, "\n\t").empty(), unseen(*text, "\n\t"));
    const std::size_t who = page.find("data-mistake=\"a_mistake\"");
    REQUIRE(who != std::string::npos);
    const std::string row = page.substr(who, page.find("</tr>", who) - who);
    CHECK(row.find(">\\xE2\\x80\\xAEgnissim</a>") != std::string::npos);
    CHECK(row.find(">b\\xE2\\x81\\xA6x\\xE2\\x80\\x8F</a>") != std::string::npos);
    const std::size_t title = pair.find("<title>");
    REQUIRE(title != std::string::npos);
    CHECK(pair.substr(title, pair.find("</title>") - title).find("\\xE2\\x80\\xAEgnissim") != std::string::npos);
    CHECK(page.find("\\xE2\\x80\\xAEreversed") != std::string::npos); // a problem's text too
    for (const char* file : {"gradebook-moodle.csv", "gradebook-canvas.csv"}) {
        const std::string text = readFile(out / file);
        CHECK_MESSAGE(unseen(text).empty(), unseen(text));
    }
}

TEST_CASE("a safe name gives back the folder's bytes it was made from, but for a cut one") {
    for (const Name& n : names()) {
        CAPTURE(n.shown);
        const std::string safe = raylab::grader::safeStudentName(n.folder);
        const std::optional<std::string> folder = raylab::grader::studentFolderName(safe);
        if (safe.find('~') == std::string::npos) CHECK(folder == n.folder);
        else CHECK_FALSE(folder);
    }
    CHECK_FALSE(raylab::grader::studentFolderName(repeated("%E9", 255).substr(0, 143) + "~0123456789ABCDEF"));
    CHECK_FALSE(raylab::grader::studentFolderName("%4")); // no safe name
    CHECK_FALSE(raylab::grader::studentFolderName("%41")); // 'A' is kept: the safe name of A is A
    CHECK_FALSE(raylab::grader::studentFolderName(""));
}

} // TEST_SUITE

namespace {

// Whether a spreadsheet would run `cell` as a formula: it starts with = + - @, a tab or a carriage
// return, and is not a plain number.
bool formula(const std::string& cell) {
    static const std::regex number(R"([+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?)");
    return !cell.empty() && std::string("=+-@\t\r").find(cell[0]) != std::string::npos && !std::regex_match(cell, number);
}

// The CSV files of the class: grades.csv and both gradebooks without a roster (copied into
// root/no-roster), then both with one (in OUT, with grades.csv).
std::vector<fs::path> csvFiles() {
    const GradedClass& graded = gradedClass();
    const fs::path copy = graded.root / "no-roster";
    fs::remove_all(copy);
    fs::create_directories(copy);
    for (const char* file : {"grades.csv", "gradebook-moodle.csv", "gradebook-canvas.csv"})
        fs::copy_file(graded.out / file, copy / file);
    const fs::path roster = graded.root / "roster-spreadsheets.csv";
    std::ofstream(roster, std::ios::binary) << "folder,id,name,email\n"
                                               "a\\b,=1+1;,\"a\n=3+3\",\"x;=1+1;@SUM(2)\"\n"
                                               "H\xE9lo\xEFse;=1+1;,\t-1+2,\"\xE2\x80\xAE;+4+4\",\"@A1,=5+5\r\n-6+6\"\n"
                                               "zoe,1,\"Zo\xC3\xAB; -\",\"z,\t=2\"\n";
    const ProgramRun run = runProgram({(binDir() / "raylab").string(), "class-page", graded.out.string(), "--roster",
                                       roster.string(), "--lang", "en"},
                                      graded.root / "output-spreadsheets.txt");
    REQUIRE_MESSAGE(run.status == 0, run.output);
    return {copy / "grades.csv", copy / "gradebook-moodle.csv", copy / "gradebook-canvas.csv",
            graded.out / "gradebook-moodle.csv", graded.out / "gradebook-canvas.csv"};
}

} // namespace

TEST_SUITE("class names python") {

TEST_CASE("every CSV file read by Python's csv with ',' gives its cells, and with ';' (as French Excel or LibreOffice "
          "asked for ';' splits) no formula; nor split at either separator or a line break ignoring the quotes") {
    const fs::path python = neededProgram("python3", "python3");
    if (python.empty()) return;
    const std::vector<fs::path> files = csvFiles();
    const fs::path script = gradedClass().root / "read_csv.py";
    std::ofstream(script) << "import csv, json, sys\n"
                             "read = {}\n"
                             "for path in sys.argv[1:]:\n"
                             "    read[path] = {}\n"
                             "    for d in ',;':\n"
                             "        with open(path, newline='', encoding='utf-8') as f:\n"
                             "            read[path][d] = list(csv.reader(f, delimiter=d))\n"
                             "print(json.dumps(read))\n";
    std::vector<std::string> argv{python.string(), script.string()};
    for (const fs::path& file : files) argv.push_back(file.string());
    const ProgramRun run = runProgram(argv, gradedClass().root / "python-output.txt");
    REQUIRE_MESSAGE(run.status == 0, run.output);
    const nlohmann::json read = nlohmann::json::parse(run.output);
    for (const fs::path& file : files) {
        CAPTURE(file);
        const std::string text = readFile(file);
        const auto ours = readCsv(text);
        CHECK(read.at(file.string()).at(",").get<std::vector<std::vector<std::string>>>() == ours);
        for (const auto& row : read.at(file.string()).at(";").get<std::vector<std::vector<std::string>>>())
            for (const std::string& cell : row) CHECK_MESSAGE(!formula(cell), raylab::printableName(cell));
        // A reader that ignores the quotes: every piece between separators and line breaks, its quotes dropped.
        for (const char separator : {',', ';'}) {
            std::string piece;
            for (std::size_t k = 0; k <= text.size(); ++k) {
                const char c = k < text.size() ? text[k] : '\n';
                if (c == separator || c == '\n' || c == '\r') {
                    const std::size_t start = piece.find_first_not_of('"');
                    const std::string cell = start == std::string::npos ? "" : piece.substr(start);
                    CHECK_MESSAGE(!formula(cell), separator << " " << raylab::printableName(cell));
                    piece.clear();
                } else {
                    piece += c;
                }
            }
        }
    }
}

} // TEST_SUITE

TEST_SUITE("class names libreoffice") {

TEST_CASE("LibreOffice opens every CSV file, split at ',' and at ';', without a formula") {
    fs::path office = raylab::grader::findProgram("soffice");
    if (office.empty()) office = neededProgram("libreoffice", "libreoffice-calc");
    if (office.empty()) return;
    const std::vector<fs::path> files = csvFiles();
    for (const char* separator : {"44", "59"}) {
        CAPTURE(separator);
        const fs::path converted = gradedClass().root / ("libreoffice-" + std::string(separator));
        fs::remove_all(converted);
        std::size_t k = 0;
        for (const fs::path& file : files) {
            // Each file under a name of its own, converted to a flat OpenDocument sheet: a formula is a table:formula.
            const fs::path input = converted / ("in" + std::to_string(k++) + ".csv");
            fs::create_directories(converted);
            fs::copy_file(file, input);
            const ProgramRun run = runProgram({office.string(), "-env:UserInstallation=file://" + (converted / "profile").string(),
                                               "--headless", "--norestore", "--infilter=CSV:" + std::string(separator) + ",34,76,1",
                                               "--convert-to", "fods", "--outdir", converted.string(), input.string()},
                                              converted / "output.txt");
            REQUIRE_MESSAGE(run.status == 0, run.output);
            const std::string sheet = readFile(fs::path(input).replace_extension(".fods"));
            CAPTURE(file);
            REQUIRE_MESSAGE(sheet.find("<office:document") != std::string::npos, run.output);
            CHECK(sheet.find("table:formula=") == std::string::npos);
        }
    }
}

} // TEST_SUITE
