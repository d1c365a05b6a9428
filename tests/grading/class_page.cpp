// The class page (issue 36): made from a class run's results, its pass rates and mistake counts agree
// with each student's own report (results.json); it opens in headless chromium; the gradebook files
// have a row per roster student and name the unknown and missing; similar submissions put a copied
// pair, renamed and laid out otherwise, above students who wrote their own lab 3.
#include "grader/class_page/class_page.h"
#include "grader/class_page/gradebook.h"
#include "grader/class_page/similarity.h"
#include "grader/course/class_run.h"
#include "grader/sandbox/sandbox.h"
#include "grading_support.h"
#include "src/atomic_file.h"
#include "support/files.h"
#include "support/needs.h"
#include "support/read_csv.h"
#include "support/run_program.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

using namespace raylab::test;

namespace {

// Four runs of grade-class into one OUT, each class folder graded by one agent: two students with
// the reference, two with lab 1's i and j swapped, one with lab 3's cos(dot), one whose lab 2 crashes.
fs::path gradedClass(const std::string& name) {
    const fs::path root = freshFolder(name), out = root / "out";
    const std::vector<std::pair<std::string, std::vector<std::string>>> runs{
        {"raylab-agent-reference", {"ada", "ben"}}, {"raylab-mistake-i_j_swapped", {"cleo", "dan"}},
        {"raylab-mistake-cos_of_dot", {"eve"}}, {"raylab-bad-crash", {"fay"}}};
    for (const auto& [agent, students] : runs) {
        const fs::path classDir = root / ("class-" + agent);
        for (const std::string& s : students) {
            fs::create_directories(classDir / s / "lab1_first_image");
            std::ofstream(classDir / s / "lab1_first_image" / "gradient.cpp") << "// " << s << "\n";
        }
        std::vector<std::string> args{(binDir() / "raylab").string(), "grade-class", classDir.string(), "--out", out.string(),
                                      "--agent", (binDir() / agent).string(), "--threads", "2", "--timeout", "60"};
        if (!bubblewrapMissing().empty()) args.push_back("--no-sandbox");
        const ProgramRun run = runProgram(args, root / ("output-" + agent + ".txt"));
        REQUIRE_MESSAGE(run.status == 0, run.output);
    }
    return out;
}

// The page's rows that carry `attribute` (data-item, data-mistake ...): the row's attributes, by that one's value.
std::map<std::string, std::map<std::string, std::string>> rowsWith(const std::string& page, const std::string& attribute) {
    std::map<std::string, std::map<std::string, std::string>> rows;
    const std::regex row("<tr ([^>]*" + attribute + "=[^>]*)>"), attr(R"re(([a-z-]+)="([^"]*)")re");
    for (auto it = std::sregex_iterator(page.begin(), page.end(), row); it != std::sregex_iterator(); ++it) {
        std::map<std::string, std::string> values;
        const std::string inside = (*it)[1];
        for (auto a = std::sregex_iterator(inside.begin(), inside.end(), attr); a != std::sregex_iterator(); ++a)
            values[(*a)[1]] = (*a)[2];
        rows[values[attribute]] = values;
    }
    return rows;
}

// Each student's own report (the Gradescope results.json grade-class wrote for them).
std::vector<nlohmann::json> studentReports(const fs::path& out) {
    std::vector<nlohmann::json> reports;
    for (const auto& entry : fs::directory_iterator(out / "students"))
        reports.push_back(nlohmann::json::parse(readFile(entry.path() / "report" / "results.json")));
    return reports;
}

} // namespace

TEST_SUITE("class page") {

TEST_CASE("pass rates and mistake counts agree with each student's report; class-page remakes the page alone") {
    const fs::path out = gradedClass("raylab-class-page");
    const std::string page = readFile(out / "index.html");
    REQUIRE(!page.empty());
    CHECK(page.find("The class: 6 students graded") != std::string::npos);
    CHECK(page.find("<svg") != std::string::npos);

    // Figures: a test named after the figure's id in every report; checks: the sums over every item.
    const std::vector<nlohmann::json> reports = studentReports(out);
    REQUIRE(reports.size() == 6);
    const auto items = rowsWith(page, "data-item");
    int passedOnPage = 0, gradedOnPage = 0, passedInReports = 0, gradedInReports = 0;
    for (const auto& [name, row] : items) {
        passedOnPage += std::stoi(row.at("data-passed"));
        gradedOnPage += std::stoi(row.at("data-graded"));
        if (name.rfind("lab", 0) != 0 || name.find(':') != std::string::npos) continue; // a check
        int passed = 0, graded = 0;
        for (const nlohmann::json& r : reports)
            for (const nlohmann::json& t : r["tests"])
                if (t["name"].get<std::string>().find("figure " + name) != std::string::npos) {
                    ++graded;
                    passed += t["status"] == "passed" ? 1 : 0;
                }
        CHECK_MESSAGE(std::stoi(row.at("data-passed")) == passed, name);
        CHECK_MESSAGE(std::stoi(row.at("data-graded")) == graded, name);
    }
    for (const nlohmann::json& r : reports)
        for (const nlohmann::json& t : r["tests"]) {
            ++gradedInReports;
            passedInReports += t["status"] == "passed" ? 1 : 0;
        }
    CHECK(passedOnPage == passedInReports);
    CHECK(gradedOnPage == gradedInReports);
    CHECK(items.at("lab1_gradient").at("data-passed") == "4"); // the two with i and j swapped fail it
    // The least passed first.
    CHECK(page.find("data-item=\"lab1_gradient\"") < page.find("data-item=\"lab4_a\""));

    // Mistakes: as many students as reports that name the mistake.
    const auto mistakes = rowsWith(page, "data-mistake");
    for (const auto& [id, name] : std::map<std::string, std::string>{{"i_j_swapped", "'i and j swapped"}}) {
        int named = 0;
        for (const nlohmann::json& r : reports) named += r.dump().find(name) != std::string::npos ? 1 : 0;
        REQUIRE_MESSAGE(mistakes.count(id), page);
        CHECK(std::stoi(mistakes.at(id).at("data-students")) == named);
        CHECK(named == 2);
    }
    CHECK(page.find("students/cleo/report/index.html") != std::string::npos);
    // The crash: fay alone among the code that stopped.
    const auto trouble = rowsWith(page, "data-student");
    CHECK(trouble.size() == 1);
    CHECK(trouble.count("fay") == 1);

    // Remade alone, from the results, in French: the same counts.
    fs::remove(out / "index.html");
    const ProgramRun remade = runProgram({(binDir() / "raylab").string(), "class-page", out.string(), "--lang", "fr"},
                                         out.parent_path() / "class-page.txt");
    REQUIRE_MESSAGE(remade.status == 0, remade.output);
    const std::string french = readFile(out / "index.html");
    CHECK(french.find("La classe\u00A0: 6 étudiants notés") != std::string::npos);
    CHECK(rowsWith(french, "data-item") == items);
    CHECK(rowsWith(french, "data-mistake").at("i_j_swapped").at("data-students") == "2");

    // With a roster: a Moodle row per roster student, the one graded but not listed and the one listed but
    // not graded named on the console and the page.
    std::ofstream(out / "roster.csv") << "folder,id,name,email\nada,1,Ada,a@x.org\nben,2,Ben,b@x.org\ncleo,3,Cleo,c@x.org\n"
                                         "dan,4,Dan,d@x.org\neve,5,Eve,e@x.org\nzed,6,Zed,z@x.org\n";
    const ProgramRun rostered = runProgram({(binDir() / "raylab").string(), "class-page", out.string(), "--roster",
                                            (out / "roster.csv").string()},
                                           out.parent_path() / "class-page-roster.txt");
    REQUIRE_MESSAGE(rostered.status == 0, rostered.output);
    CHECK_MESSAGE(rostered.output.find("Graded but not in the roster (1), so in neither gradebook file: fay") != std::string::npos,
                  rostered.output);
    CHECK_MESSAGE(rostered.output.find("In the roster but not graded (1), their grades left empty: zed") != std::string::npos,
                  rostered.output);
    const auto moodle = readCsv(readFile(out / "gradebook-moodle.csv"));
    CHECK(moodle.size() == 7); // the header and the roster's six
    CHECK(readFile(out / "index.html").find("id=\"roster_missing\"") != std::string::npos);
}

TEST_CASE("code that did not build: every lab of the outcome says so, every item failed") {
    const raylab::grader::GradeSetup setup = courseSetup();
    const raylab::grader::StudentOutcome outcome = raylab::grader::outcomeOf(raylab::grader::gradeBuildFailure(setup, "error: x"));
    fs::remove_all(setup.scratch);
    REQUIRE(!outcome.labs.empty());
    for (const auto& lab : outcome.labs) CHECK(lab.unbuilt);
    for (const auto& item : outcome.items) CHECK(!item.passed);
    REQUIRE(!outcome.problems.empty());
    CHECK(outcome.problems[0].find("error: x") != std::string::npos);
}

} // TEST_SUITE

// Its own suite: skipped without chromium (support/needs.h).
TEST_SUITE("class page browser") {

TEST_CASE("the class page opens in headless chromium, offline, with its plots") {
    const fs::path chromium = neededProgram("chromium", "chromium");
    if (chromium.empty()) return;
    const fs::path out = gradedClass("raylab-class-page-browser");
    const fs::path profile = out.parent_path() / "chromium-profile";
    const ProgramRun run = runProgram({chromium.string(), "--headless", "--no-sandbox", "--disable-gpu",
                                       "--disable-background-networking", "--no-first-run", "--user-data-dir=" + profile.string(),
                                       "--dump-dom", "file://" + fs::absolute(out / "index.html").string()},
                                      out.parent_path() / "dom.txt");
    REQUIRE_MESSAGE(run.status == 0, run.output);
    CHECK(run.output.find("<title>The class: 6 students graded</title>") != std::string::npos);
    CHECK(run.output.find("<svg") != std::string::npos);
    CHECK(run.output.find("data-item=\"lab1_gradient\"") != std::string::npos);
    CHECK(run.output.find("src=\"http") == std::string::npos); // nothing fetched from anywhere
    CHECK(run.output.find("href=\"http") == std::string::npos);
}

} // TEST_SUITE

namespace {

// A finished result and outcome for `name` in OUT, as a class run leaves them.
void addResult(const fs::path& out, const std::string& name, const std::vector<raylab::grader::LabScore>& labs) {
    const fs::path folder = out / "students" / raylab::grader::safeStudentName(name);
    fs::create_directories(folder);
    raylab::grader::StudentOutcome outcome;
    outcome.labs = labs;
    raylab::grader::writeStudentOutcome(outcome, folder / "outcome.json");
    raylab::writeFileAtomically(folder / "result.json", nlohmann::json{{"student", name}, {"cells", nlohmann::json::array()}}.dump());
}

} // namespace

TEST_SUITE("class page gradebook") {

TEST_CASE("Moodle and Canvas files: a row per roster student, the unknown and the missing named") {
    const fs::path out = freshFolder("raylab-gradebook");
    addResult(out, "ada", {{1, 2., 2., false}, {3, 5., 8., false}});
    addResult(out, "ben", {{1, 0., 2., true}, {3, 8., 8., false}});
    addResult(out, "stray", {{1, 2., 2., false}, {3, 8., 8., false}});
    std::ofstream(out / "roster.csv") << "\xEF\xBB\xBF" "folder,id,name,email\r\nada,1001,\"Lovelace, Ada\",ada@example.org\r\n"
                                         "ben,1002,Ben,ben@example.org\r\nzoe,1003,Zoe,zoe@example.org\r\n";
    const auto roster = raylab::grader::readRoster(out / "roster.csv");
    REQUIRE(roster.size() == 3);
    const raylab::grader::GradebookFiles files =
        raylab::grader::writeGradebooks(raylab::grader::loadClassResults(out), roster, out);
    CHECK(files.unknown == std::vector<std::string>{"stray"});
    CHECK(files.missing == std::vector<std::string>{"zoe"});
    const auto moodle = readCsv(readFile(out / "gradebook-moodle.csv"));
    REQUIRE(moodle.size() == 4); // the header, a row per roster student
    CHECK(moodle[0] == std::vector<std::string>{"ID number", "Email address", "Full name", "lab1", "lab3", "total"});
    CHECK(moodle[1] == std::vector<std::string>{"1001", "ada@example.org", "Lovelace, Ada", "2", "5", "7"});
    CHECK(moodle[2] == std::vector<std::string>{"1002", "ben@example.org", "Ben", "0", "8", "8"});
    CHECK(moodle[3] == std::vector<std::string>{"1003", "zoe@example.org", "Zoe", "", "", ""});
    const auto canvas = readCsv(readFile(out / "gradebook-canvas.csv"));
    REQUIRE(canvas.size() == 4);
    CHECK(canvas[0] == std::vector<std::string>{"Name", "SID", "Email", "lab1", "lab3", "total"});
    CHECK(canvas[1] == std::vector<std::string>{"Lovelace, Ada", "1001", "ada@example.org", "2", "5", "7"});

    // Without a roster: a row per graded student, known by their folder's name.
    const auto byFolder = raylab::grader::writeGradebooks(raylab::grader::loadClassResults(out), {}, out);
    CHECK(byFolder.unknown.empty());
    CHECK(readCsv(readFile(out / "gradebook-moodle.csv")).size() == 4);
}

TEST_CASE("a wrong roster is an error naming the file, the line and the problem") {
    const fs::path dir = freshFolder("raylab-roster-errors");
    const auto problem = [&](const std::string& text) {
        std::ofstream(dir / "roster.csv") << text;
        try {
            raylab::grader::readRoster(dir / "roster.csv");
        } catch (const std::exception& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    CHECK(problem("folder,name\nada,Ada\n").find("roster.csv:1: no column 'id'") != std::string::npos);
    CHECK(problem("folder,id\nada,1\nada,2\n").find("roster.csv:3: the folder 'ada' is given twice") != std::string::npos);
    CHECK(problem("folder,id\nada,\n").find("roster.csv:2: no id for 'ada'") != std::string::npos);
    CHECK(problem("folder,id\n\"ada,1\n").find("line 2: a quote is opened and never closed") != std::string::npos);
}

} // TEST_SUITE

namespace {

// A student whose lab 3 is the solution with these lab files replaced (from a patched copy in the build).
void addLab3(const fs::path& out, const std::string& name, const fs::path& patched = {}) {
    const fs::path lab = out / "students" / name / "submission" / "lab3_sphere";
    fs::create_directories(lab);
    for (const char* file : {"sphere_geometry.cpp", "ray_cast_integrator.cpp"}) {
        const fs::path own = patched / "lab3_sphere" / file;
        fs::copy_file(!patched.empty() && fs::exists(own) ? own : sourceDir() / "solutions/lab3_sphere" / file, lab / file);
    }
    addResult(out, name, {{3, 8., 8., false}});
}

std::string replaced(std::string text, const std::vector<std::pair<std::string, std::string>>& words) {
    for (const auto& [from, to] : words) text = std::regex_replace(text, std::regex("\\b" + from + "\\b"), to);
    return text;
}

} // namespace

TEST_SUITE("class page similarity") {

TEST_CASE("a copied lab 3, renamed and laid out otherwise, tops the list; students who wrote their own do not") {
    if (raylab::grader::findProgram("sim_c++").empty()) {
        MESSAGE("skipped: needs sim_c++ (" << raylab::grader::installCommand("similarity-tester", "", "") << ")");
        return;
    }
    const fs::path out = freshFolder("raylab-similarity"), submissions = fs::path(RAYLAB_BUILD_DIR) / "submissions";
    // Their own lab 3: the solution, and catalogued mistakes (each a change of a line or more to it).
    addLab3(out, "ref");
    addLab3(out, "textbook", submissions / "mistake/textbook_quadratic");
    addLab3(out, "cos", submissions / "mistake/cos_of_dot");
    addLab3(out, "gamma", submissions / "mistake/gamma_applied");
    addLab3(out, "far", submissions / "mistake/far_root_first"); // the solution's tokens in another order
    // The copied pair: another correct lab 3 (computed in double), and its copy renamed and laid out otherwise.
    addLab3(out, "copier_a", submissions / "variant/double_precision");
    addLab3(out, "copier_b", submissions / "variant/double_precision");
    const fs::path copy = out / "students/copier_b/submission/lab3_sphere/sphere_geometry.cpp";
    std::string text = replaced(readFile(copy), {{"oc", "fromCentre"}, {"disc", "delta"}, {"root", "sq"}, {"t", "dist"}});
    text = std::regex_replace(text, std::regex("    "), "\t");
    text = std::regex_replace(text, std::regex("\\) \\{"), ")\n{");
    fs::remove(copy);
    std::ofstream(copy) << text;

    const auto catalog = raylab::grader::loadLabCatalog(sourceDir() / "labs");
    const auto report = raylab::grader::findSimilarSubmissions(raylab::grader::loadClassResults(out), catalog,
                                                               sourceDir() / "labs", out / "compared");
    CHECK(report.note.empty());
    const auto lab3 = std::find_if(report.labs.begin(), report.labs.end(), [](const auto& l) { return l.lab == 3; });
    REQUIRE(lab3 != report.labs.end());
    REQUIRE(!lab3->pairs.empty());
    const auto& top = lab3->pairs[0];
    CHECK(std::set<std::string>{lab3->students[top.first], lab3->students[top.second]} ==
          std::set<std::string>{"copier_a", "copier_b"});
    CHECK(top.overlap == 100);
    for (std::size_t k = 1; k < lab3->pairs.size(); ++k) CHECK(lab3->pairs[k].overlap < top.overlap);
    CHECK(top.unusual);
    CHECK(!top.runs.empty());
    // The solution, written alike by most of this class, is nobody's own: its student has no pair.
    CHECK(std::find(lab3->students.begin(), lab3->students.end(), "ref") == lab3->students.end());
    CHECK(std::find(lab3->students.begin(), lab3->students.end(), "textbook") != lab3->students.end());
    const std::size_t n = lab3->students.size();
    CHECK(lab3->comparedPairs == n * (n - 1) / 2);
    CHECK(lab3->median < top.overlap);
    // The other labs: nobody wrote code there.
    for (const auto& lab : report.labs)
        if (lab.lab != 3) CHECK(lab.pairs.empty());
}

TEST_CASE("without sim_c++: a note that says so and how to install it, no pairs") {
    const fs::path out = freshFolder("raylab-similarity-absent");
    addLab3(out, "ref");
    addLab3(out, "again");
    const char* path = std::getenv("PATH");
    const std::string ourPath = path ? path : "";
    setenv("PATH", "/nonexistent", 1);
    const auto catalog = raylab::grader::loadLabCatalog(sourceDir() / "labs");
    const auto report = raylab::grader::findSimilarSubmissions(raylab::grader::loadClassResults(out), catalog,
                                                               sourceDir() / "labs", out / "compared");
    setenv("PATH", ourPath.c_str(), 1);
    CHECK(report.labs.empty());
    CHECK(report.note.find("sim_c++ (Debian's similarity-tester) is not installed") != std::string::npos);
    CHECK(report.note.find("apt-get install -y similarity-tester") != std::string::npos);
}

} // TEST_SUITE

// A benchmark, no timed assertion: `raylab class-page` on a class of 100, the page and the similar
// submissions of every lab (docs/grading.md quotes its figure).
TEST_SUITE("class page benchmark") {

TEST_CASE("class-page on a class of 100 students: the time it takes") {
    const fs::path out = freshFolder("raylab-class-page-100"), submissions = fs::path(RAYLAB_BUILD_DIR) / "submissions";
    std::vector<fs::path> versions{{}}; // the solution, each mistake and variant: whichever labs they change
    for (const char* kind : {"mistake", "variant"})
        for (const auto& entry : fs::directory_iterator(submissions / kind)) versions.push_back(entry.path());
    const auto catalog = raylab::grader::loadLabCatalog(sourceDir() / "labs");
    for (int s = 0; s < 100; ++s) {
        const std::string name = "student" + std::to_string(s);
        const fs::path copy = out / "students" / name / "submission";
        std::vector<raylab::grader::LabScore> labs;
        raylab::grader::StudentOutcome outcome;
        for (const auto& lab : catalog.labs) {
            const fs::path& version = versions[std::size_t(s * 7 + lab.number) % versions.size()];
            fs::create_directories(copy / lab.id);
            for (const std::string& file : lab.files()) {
                const fs::path own = version / lab.id / file;
                const std::string text = readFile(!version.empty() && fs::exists(own) ? own : sourceDir() / "solutions" / lab.id / file);
                std::ofstream(copy / lab.id / file) << "// " << name << "\n" << text; // a line of their own, at least
            }
            outcome.labs.push_back({lab.number, double(s % 9), 8., false});
            for (const auto& check : lab.checks) outcome.items.push_back({false, lab.number, check.id, (s + lab.number) % 3 != 0, false, {}});
        }
        raylab::grader::writeStudentOutcome(outcome, out / "students" / name / "outcome.json");
        raylab::writeFileAtomically(out / "students" / name / "result.json",
                                    nlohmann::json{{"student", name}, {"cells", nlohmann::json::array()}}.dump());
    }
    const auto start = std::chrono::steady_clock::now();
    const ProgramRun run = runProgram({(binDir() / "raylab").string(), "class-page", out.string()}, out.parent_path() / "bench.txt");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    REQUIRE_MESSAGE(run.status == 0, run.output);
    std::printf("class-page, 100 students, %zu labs, sim_c++ %s: %.2f s\n", catalog.labs.size(),
                raylab::grader::findProgram("sim_c++").empty() ? "absent" : "present", seconds);
    CHECK(fs::exists(out / "index.html"));
}

} // TEST_SUITE
