// The commands as a user runs them: raylab grade --images, raylab grade (reports), raylab distribute.
#include "grading_support.h"

#include "raylab/image_io.h"

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <fstream>
#include <sstream>
#if defined(__unix__) || defined(__APPLE__)
#include <sys/wait.h>
#endif

using namespace raylab::test;

namespace {

struct Run {
    int status = -1;
    std::string output;
};

// Runs `raylab ARGS` from `cwd`; its output and exit status.
Run runRaylab(const std::string& args, const fs::path& cwd = fs::temp_directory_path()) {
    const fs::path out = cwd / "raylab-output.txt";
    const std::string command = "cd \"" + cwd.string() + "\" && \"" + (binDir() / "raylab").string() + "\" " + args +
                                " > \"" + out.string() + "\" 2>&1";
    const int raw = std::system(command.c_str());
    Run run;
#if defined(__unix__) || defined(__APPLE__)
    run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
#else
    run.status = raw;
#endif
    std::ifstream in(out);
    std::stringstream text;
    text << in.rdbuf();
    run.output = text.str();
    return run;
}

fs::path freshFolder(const std::string& name) {
    const fs::path folder = fs::temp_directory_path() / name;
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

bool hasLine(const std::string& output, const std::string& start, const std::string& contains) {
    std::istringstream lines(output);
    for (std::string line; std::getline(lines, line);)
        if (line.rfind(start, 0) == 0 && line.find(contains) != std::string::npos) return true;
    return false;
}

} // namespace

TEST_SUITE("commands") {

TEST_CASE("grade --images: a line per figure, a clear FAIL for each bad file, the rest still graded") {
    const fs::path refs = referencesDir();
    const fs::path dir = freshFolder("raylab-images-test");
    const fs::path report = dir / "report";
    for (const char* id : {"lab1_gradient", "lab3_flat", "lab5_antialiased"})
        fs::copy_file(refs / (std::string(id) + ".png"), dir / (std::string(id) + ".png"));
    Run run = runRaylab("grade --images \"" + dir.string() + "\" --report \"" + report.string() + "\"");
    CHECK_MESSAGE(run.status == 0, run.output);
    CHECK(hasLine(run.output, "PASS  lab5_antialiased", "unbiased"));
    CHECK(hasLine(run.output, "FAIL  lab4_a", "missing"));

    std::ofstream(dir / "lab2_directions.png") << "this is text, not a picture";
    {
        std::ifstream whole(refs / "lab3_cosine.png", std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(whole)), {});
        std::ofstream(dir / "lab3_cosine.png", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    }
    raylab::Image8 small{300, 200, std::vector<std::uint8_t>(300 * 200 * 3, 128)};
    raylab::writePng(dir / "lab4_b.png", small);
    run = runRaylab("grade --images \"" + dir.string() + "\" --report \"" + report.string() + "\"");
    CHECK(run.status == 1);
    CHECK_MESSAGE(hasLine(run.output, "FAIL  lab2_directions", "not a PNG"), run.output);
    CHECK_MESSAGE(hasLine(run.output, "FAIL  lab3_cosine", "unreadable"), run.output);
    CHECK_MESSAGE(hasLine(run.output, "FAIL  lab4_b", "300 x 200"), run.output);
    CHECK(hasLine(run.output, "PASS  lab1_gradient", ""));
    CHECK(hasLine(run.output, "PASS  lab3_flat", ""));
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
    const Run run = runRaylab("grade --images \"" + (dir / "figures").string() + "\" --report \"" + (dir / "report").string() + "\"");
    CHECK(run.status == 1);
    CHECK_MESSAGE(run.output.find("your image matches 'v flipped (upside-down image)'") != std::string::npos, run.output);
}

TEST_CASE("grade writes index.html, results.json and junit.xml that agree") {
    const fs::path dir = freshFolder("raylab-grade-report");
    const Run run = runRaylab("grade --agent \"" + (binDir() / "raylab-mistake-samples_not_divided").string() +
                           "\" --report \"" + (dir / "report").string() + "\"", dir);
    CHECK(run.status == 1);
    CHECK(hasLine(run.output, "  FAIL  lab5  renderPixel: N rays and their average", ""));
    std::ifstream in(dir / "report" / "results.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    double sum = 0.;
    for (const auto& t : j["tests"]) sum += t["score"].get<double>();
    CHECK(j["score"].get<double>() == doctest::Approx(sum));
    CHECK(j["score"].get<double>() < j["max_score"].get<double>());
    CHECK(fs::exists(dir / "report" / "junit.xml"));
    CHECK(fs::exists(dir / "report" / "index.html"));
}

TEST_CASE("distribute writes a tree without the solutions, with the references") {
    const fs::path out = fs::temp_directory_path() / "raylab-distribute-test";
    fs::remove_all(out);
    const Run run = runRaylab("distribute \"" + out.string() + "\"");
    CHECK_MESSAGE(run.status == 0, run.output);
    CHECK_FALSE(fs::exists(out / "solutions"));
    CHECK_FALSE(fs::exists(out / "tests/mistakes"));
    CHECK_FALSE(fs::exists(out / "tests/variants"));
    CHECK(fs::exists(out / "labs/lab3_sphere/sphere_geometry.cpp"));
    CHECK(fs::exists(out / "framework/grader/data/references/lab5_antialiased.sd.png"));
    CHECK(fs::exists(out / "labs/lab3_sphere/lab.toml"));
    CHECK(fs::exists(out / "CMakeLists.txt"));
    CHECK(runRaylab("distribute \"" + out.string() + "\"").status != 0); // never over an existing tree
}

} // TEST_SUITE

TEST_SUITE("commands") {

TEST_CASE("grade --lab N grades that lab alone") {
    const fs::path dir = freshFolder("raylab-grade-lab");
    const Run run = runRaylab("grade --lab 5 --agent \"" + (binDir() / "raylab-mistake-i_j_swapped").string() +
                              "\" --report \"" + (dir / "report").string() + "\"", dir);
    CHECK_MESSAGE(run.status == 0, run.output); // the mistake is in lab 1
    CHECK(run.output.find("lab1") == std::string::npos);
    CHECK(hasLine(run.output, "  total: 13 / 13", ""));
}

} // TEST_SUITE
