// The commands as a user runs them: raylab grade --images, raylab grade (reports), raylab distribute.
#include "support/files.h"
#include "grading_support.h"
#include "support/course.h"

#include "raylab/image_io.h"

#include <nlohmann/json.hpp>

#include "support/run_program.h"

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

using namespace raylab::test;

namespace {

// The language comes from the environment: every run here is English unless a Locale says otherwise.
class Locale {
public:
    explicit Locale(const char* lang) { set(lang); }
    ~Locale() { set("C"); }
    Locale(const Locale&) = delete;
    Locale& operator=(const Locale&) = delete;

private:
    static void set(const char* lang) {
        unsetenv("LC_ALL");
        unsetenv("LC_MESSAGES");
        setenv("LANG", lang, 1);
    }
};

// Runs `raylab ARGS` from `cwd`; its output and exit status.
ProgramRun runRaylab(std::vector<std::string> args, const fs::path& cwd = fs::temp_directory_path()) {
    static const Locale english("C");
    args.insert(args.begin(), (binDir() / "raylab").string());
    return runProgram(args, cwd / "raylab-output.txt", cwd);
}

using raylab::test::freshFolder;

bool hasLine(const std::string& output, const std::string& start, const std::string& contains) {
    std::istringstream lines(output);
    for (std::string line; std::getline(lines, line);)
        if (line.rfind(start, 0) == 0 && line.find(contains) != std::string::npos) return true;
    return false;
}

} // namespace

// Words of English sentences that no French message holds.
const char* const kEnglishWords[] = {" the ", " is ", " are ", " of ", " and ", "expected", " got ", "Hint", "failed",
                                     "passed", "not done yet", "PASS", "FAIL", "report:", "total:"};

void checkFrenchOnly(const ProgramRun& run) {
    for (const char* word : kEnglishWords)
        CHECK_MESSAGE(run.output.find(word) == std::string::npos, "\"" << std::string(word) << "\" in\n" << run.output);
    CHECK_MESSAGE(run.output.find("total\u00A0: ") != std::string::npos, run.output);
}

TEST_SUITE("commands") {

TEST_CASE("grade --images: a line per figure, a clear FAIL for each bad file, the rest still graded") {
    // The course's figures (the catalogue's, in order): the first and the last right, the second
    // missing; then the second not a PNG, the third cut short, the fourth of another size.
    std::vector<std::string> figures;
    for (const LabDescription& lab : loadLabCatalog(sourceDir() / "labs").labs)
        for (const LabFigure& figure : lab.figures) figures.push_back(figure.id);
    REQUIRE(figures.size() >= 5);
    const fs::path dir = freshFolder("raylab-images-test");
    const fs::path report = dir / "report";
    for (const std::string& id : {figures[0], figures.back()})
        fs::copy_file(referencePicture(id), dir / (id + ".png"));
    ProgramRun run = runRaylab({"grade", "--images", dir.string(), "--report", report.string()});
    CHECK_MESSAGE(run.status == 0, run.output);
    CHECK(hasLine(run.output, "PASS  " + figures.back(), ""));
    CHECK(hasLine(run.output, "FAIL  " + figures[1], "missing"));

    std::ofstream(dir / (figures[1] + ".png")) << "this is text, not a picture";
    {
        std::ifstream whole(referencePicture(figures[2]), std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(whole)), {});
        std::ofstream(dir / (figures[2] + ".png"), std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    }
    raylab::Image8 small{7, 5, std::vector<std::uint8_t>(7 * 5 * 3, 128)}; // no figure's size
    raylab::writePng(dir / (figures[3] + ".png"), small);
    run = runRaylab({"grade", "--images", dir.string(), "--report", report.string()});
    CHECK(run.status == 1);
    CHECK_MESSAGE(hasLine(run.output, "FAIL  " + figures[1], "not a PNG"), run.output);
    CHECK_MESSAGE(hasLine(run.output, "FAIL  " + figures[2], "unreadable"), run.output);
    CHECK_MESSAGE(hasLine(run.output, "FAIL  " + figures[3], "7 x 5"), run.output);
    CHECK(hasLine(run.output, "PASS  " + figures[0], ""));
    CHECK(hasLine(run.output, "PASS  " + figures.back(), ""));
    CHECK(fs::exists(report / "index.html"));
}

TEST_CASE("grade --images names the mistake a picture shows") {
    const fs::path dir = freshFolder("raylab-images-mistake");
    GradeSetup setup = courseSetup();
    // The mistake's full-size picture, rendered by its agent.
    setup.scratch = dir / "agent";
    fs::create_directories(dir / "figures");
    for (const auto& [id, picture] : renderFigures(setup, binDir() / "raylab-mistake-v_flipped"))
        raylab::writePng(dir / "figures" / (id + ".png"), picture);
    REQUIRE(fs::exists(dir / "figures" / "lab3_cosine.png"));
    const ProgramRun run = runRaylab({"grade", "--images", (dir / "figures").string(), "--report", (dir / "report").string()});
    CHECK(run.status == 1);
    CHECK_MESSAGE(run.output.find("your image matches M2.3 'v flipped (upside-down image)'") != std::string::npos, run.output);
}

namespace {

// What git and the builds make, not the project's files.
bool workspaceProduct(const fs::path& relative) {
    const std::string top = relative.begin()->string();
    return top == ".git" || top == ".cache" || top == "out" || top == "compile_commands.json" || top.rfind("build", 0) == 0;
}

// Whether the students' tree leaves out the source tree's `relative`, by the rule docs/instructors.md
// states ("The student distribution"): a folder named solutions or instructors, a grading folder's
// mistakes/, what git and the builds make.
bool leftOutByRule(const fs::path& relative) {
    const std::vector<std::string> parts(relative.begin(), relative.end());
    for (const std::string& part : parts)
        if (part == "solutions" || part == "instructors") return true;
    const bool mistakes = parts.size() >= 5 && parts[0] == "framework" && parts[1] == "grader" && parts[2] == "labs" &&
                          parts[4] == "mistakes";
    return mistakes || workspaceProduct(relative);
}

// The source tree's files, as paths from its top, but the workspace's (many files, none handed out).
std::vector<fs::path> sourceFiles() {
    std::vector<fs::path> files;
    for (auto it = fs::recursive_directory_iterator(sourceDir()); it != fs::recursive_directory_iterator(); ++it) {
        const fs::path relative = it->path().lexically_relative(sourceDir());
        if (it->is_directory() && (it->is_symlink() || workspaceProduct(relative))) it.disable_recursion_pending();
        else if (it->is_regular_file() && !it->is_symlink()) files.push_back(relative);
    }
    return files;
}

// The lab whose folder `relative` is in (labs/<lab>/, framework/grader/labs/<lab>/), or "".
std::string labOf(const fs::path& relative) {
    const std::vector<std::string> parts(relative.begin(), relative.end());
    if (parts.size() > 2 && parts[0] == "labs") return parts[1];
    if (parts.size() > 4 && parts[0] == "framework" && parts[1] == "grader" && parts[2] == "labs") return parts[3];
    return "";
}

} // namespace

TEST_CASE("distribute leaves out what the rule says, by where it lives, and nothing else") {
    const fs::path out = raylab::test::scratchPath("raylab-distribute-test");
    fs::remove_all(out);
    const std::vector<fs::path> before = sourceFiles(); // a file written meanwhile (a test's) is not asked about
    const ProgramRun run = runRaylab({"distribute", out.string()});
    REQUIRE_MESSAGE(run.status == 0, run.output);
    // Of a lab the course leaves out, its folders and its figures are absent too: a course of every
    // lab asks about all the figures.
    bool everyLab = true;
    for (const auto& lab : fs::directory_iterator(sourceDir() / "labs"))
        if (lab.is_directory() && !fs::exists(out / "labs" / lab.path().filename())) everyLab = false;
    const auto ofAbsentLab = [&](const fs::path& relative) {
        const std::string lab = labOf(relative);
        if (!lab.empty()) return !fs::exists(out / "labs" / lab);
        return !everyLab && relative.generic_string().rfind("docs/figures/", 0) == 0;
    };
    std::string wrong;
    std::size_t leftOut = 0;
    for (const fs::path& relative : before) {
        std::error_code error;
        if (!fs::exists(sourceDir() / relative, error)) continue; // removed meanwhile
        const bool shipped = fs::exists(out / relative, error);
        if (leftOutByRule(relative)) {
            ++leftOut;
            if (shipped) wrong += "\n  shipped: " + relative.generic_string();
        } else if (!shipped && !ofAbsentLab(relative)) {
            wrong += "\n  left out: " + relative.generic_string();
        }
    }
    CHECK_MESSAGE(wrong.empty(), wrong);
    CHECK(leftOut > 50); // solutions/, the grading folders' mistakes, tests/instructors/, ...
    CHECK(fs::exists(out / "framework/study/antialiasing_study.cpp")); // a study students run
    CHECK(fs::exists(out / "labs/lab3_sphere/sphere_geometry.cpp"));
    CHECK(missingReferences(out).empty());
    CHECK(runRaylab({"distribute", out.string()}).status != 0); // never over an existing tree
}

} // TEST_SUITE

TEST_SUITE("commands") {
TEST_CASE("references for one figure's scene touch that figure alone: every other file stays, byte for byte") {
    // A copy of the grader's data: the signatures of the other figures must survive, and a picture
    // whose pixels did not change must not be re-encoded (the solutions did not change: nothing may).
    const fs::path root = freshFolder("raylab-references-one-scene"), references = root / "references",
                   scenes = root / "scenes";
    copyReferences(references);
    fs::create_directories(scenes);
    fs::copy_file(sourceDir() / "labs/lab2_primary_rays/scenes/lab2_directions.toml", scenes / "lab2_directions.toml");
    std::map<std::string, std::string> before;
    for (const auto& entry : fs::recursive_directory_iterator(references))
        if (entry.is_regular_file()) before[fs::relative(entry.path(), references).generic_string()] = readFile(entry.path());
    REQUIRE(before.size() > 50);
    const ProgramRun run = runRaylab({"references", "--out", references.string(), "--scenes", scenes.string(),
                                      "--mistakes", binDir().string()}, root);
    REQUIRE_MESSAGE(run.status == 0, run.output);
    CHECK_MESSAGE(run.output.find("lab2_directions") != std::string::npos, run.output);
    CHECK_MESSAGE(run.output.find("signatures: lab2_directions") != std::string::npos, run.output);
    std::map<std::string, std::string> after;
    for (const auto& entry : fs::recursive_directory_iterator(references))
        if (entry.is_regular_file()) after[fs::relative(entry.path(), references).generic_string()] = readFile(entry.path());
    for (const auto& [file, bytes] : before) {
        const auto now = after.find(file);
        REQUIRE_MESSAGE(now != after.end(), file << " was deleted\n" << run.output);
        if (now->second == bytes) continue;
        // Only the figure asked for, where this machine draws it otherwise than the references' (another C
        // library's maths: glibc 2.41's correctly rounded tanf moves a few 8-bit values): its pictures'
        // pixels differ then, never their encoding alone.
        CHECK_MESSAGE(file.find("lab2_directions") != std::string::npos, file << " was rewritten");
        if (fs::path(file).extension() == ".png") {
            std::ofstream(root / "before.png", std::ios::binary) << bytes;
            CHECK_MESSAGE(raylab::readImage(root / "before.png").rgb != raylab::readImage(references / file).rgb, file << " was re-encoded");
        }
    }
    CHECK(after.size() == before.size());
}


TEST_CASE("grade --lab N grades that lab alone") {
    // The course's last lab, with a mistake of lab 1, which no lab uses.
    const LabDescription last = loadLabCatalog(sourceDir() / "labs").labs.back();
    REQUIRE(last.number != 1);
    const fs::path dir = freshFolder("raylab-grade-lab");
    const ProgramRun run = runRaylab({"grade", "--lab", std::to_string(last.number), "--agent",
                                      (binDir() / "raylab-mistake-i_j_swapped").string(), "--report", (dir / "report").string()},
                                     dir);
    CHECK_MESSAGE(run.status == 0, run.output);
    CHECK(run.output.find("lab1") == std::string::npos);
    const std::string points = raylab::formatNumber(labPoints(last));
    CHECK_MESSAGE(hasLine(run.output, "  total: " + points + " / " + points, ""), run.output);
}

TEST_CASE("a French grade speaks French only: the reference, the stubs and a mistake") {
    const fs::path dir = freshFolder("raylab-grade-french");
    for (const std::string agent : {"raylab-agent-reference", "raylab-agent", "raylab-mistake-fovy_not_halved"}) {
        CAPTURE(agent);
        const ProgramRun run = runRaylab({"grade", "--lang", "fr", "--agent", (binDir() / agent).string(), "--report",
                                          (dir / "report").string()},
                                         dir);
        checkFrenchOnly(run);
        if (agent == "raylab-agent-reference") CHECK(run.status == 0);
        if (agent == "raylab-agent") CHECK(run.output.find("pas encore écrit\u00A0: écrivez") != std::string::npos);
        if (agent == "raylab-mistake-fovy_not_halved") {
            CHECK(run.output.find("E2.1 «\u00A0fovy non divisé par deux\u00A0» (TP 2, PerspectiveCamera::updateViewport (perspective_camera.cpp))") != std::string::npos);
            CHECK(run.output.find("1,154701") != std::string::npos); // a decimal comma
        }
    }
    std::ifstream html(dir / "report/index.html");
    std::stringstream page;
    page << html.rdbuf();
    CHECK(page.str().find("<html lang=\"fr\">") != std::string::npos);
    CHECK(page.str().find("Tests des fonctions") != std::string::npos);
    CHECK(page.str().find("Function checks") == std::string::npos);
}

TEST_CASE("LANG=fr_FR.UTF-8 gives French without --lang, and --lang en overrides it") {
    const fs::path dir = freshFolder("raylab-grade-lang");
    const std::vector<std::string> args{"grade", "--lab", "1", "--agent", (binDir() / "raylab-agent-reference").string(),
                                        "--report", (dir / "report").string()};
    const Locale french("fr_FR.UTF-8");
    checkFrenchOnly(runRaylab(args, dir));
    std::vector<std::string> inEnglish = args;
    inEnglish.insert(inEnglish.end(), {"--lang", "en"});
    const ProgramRun english = runRaylab(inEnglish, dir);
    CHECK_MESSAGE(english.output.find("  total: 10 / 10") != std::string::npos, english.output);
    const ProgramRun figures = runRaylab({"lab", "1", "--out", (dir / "figures").string()}, dir);
    CHECK_MESSAGE(figures.output.find("1 figure\u00A0: ") != std::string::npos, figures.output);
}

} // TEST_SUITE

TEST_SUITE("commands: lab 5") {

TEST_CASE("grade --images compares lab 5's random picture with its converged reference") {
    if (!raylab::test::labInCourse(sourceDir() / "labs", 5)) return;
    const fs::path dir = freshFolder("raylab-images-lab5");
    fs::copy_file(referencePicture("lab5_antialiased"), dir / "lab5_antialiased.png");
    const ProgramRun run = runRaylab({"grade", "--images", dir.string(), "--report", (dir / "report").string()});
    CHECK_MESSAGE(hasLine(run.output, "PASS  lab5_antialiased", "unbiased"), run.output);
}

TEST_CASE("grade writes index.html, results.json and junit.xml that agree") {
    if (!raylab::test::labInCourse(sourceDir() / "labs", 5)) return;
    const fs::path dir = freshFolder("raylab-grade-report");
    const ProgramRun run = runRaylab({"grade", "--agent", (binDir() / "raylab-mistake-samples_not_divided").string(),
                                      "--report", (dir / "report").string()},
                                     dir);
    CHECK(run.status == 1);
    CHECK(hasLine(run.output, "  FAIL  lab5  renderPixel: N rays and their average", ""));
    std::ifstream in(dir / "report" / "results.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    double sum = 0.;
    for (const auto& t : j["tests"]) sum += t["score"].get<double>();
    CHECK(j["score"].get<double>() == doctest::Approx(sum));
    CHECK(j["score"].get<double>() < j["extra_data"]["max_score"].get<double>());
    CHECK(fs::exists(dir / "report" / "junit.xml"));
    CHECK(fs::exists(dir / "report" / "index.html"));
}

} // TEST_SUITE

