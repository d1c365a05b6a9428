// The labs' descriptions (labs/<lab>/lab.toml): the instructor's files, read strictly, and the
// course's own, which agree with the references.
#include "grader/lab_catalog.h"
#include "grader/judge/checks/checks.h"
#include "grader/judge/references.h"

#include "src/scene_file.h"

#include <doctest/doctest.h>

#include <fstream>
#include <random>

using namespace raylab::grader;
namespace fs = std::filesystem;

namespace {

// A scratch course: labs/<id>/lab.toml (+ the files it names) and scenes/<figure>.toml.
struct Course {
    fs::path root = fs::temp_directory_path() / ("raylab-lab-catalog-" + std::to_string(std::random_device{}()));
    Course() { fs::create_directories(root / "scenes"); }
    ~Course() { fs::remove_all(root); }
    Course(const Course&) = delete;
    Course& operator=(const Course&) = delete;

    fs::path lab(const std::string& id, const std::string& text) const {
        fs::create_directories(root / "labs" / id);
        std::ofstream(root / "labs" / id / "code.cpp") << "// stub\n";
        std::ofstream(root / "labs" / id / "lab.toml") << text;
        return root / "labs" / id / "lab.toml";
    }
    void scene(const std::string& id) const { std::ofstream(root / "scenes" / (id + ".toml")) << "[figure]\n"; }
    LabCatalog load() const { return loadLabCatalog(root / "labs", root / "scenes"); }
};

const std::string kLab2 = R"toml(number = 2
id = "lab2_rays"
title = { en = "Rays", fr = "Rayons" }
uses = [1]

[[function]]
file = "code.cpp"
name = "trace"

[[figure]]
id = "lab2_picture"
scene = "lab2_picture.toml"
handout = "2(b)"
caption = { en = "A picture", fr = "Une image" }
points = 1.5

[[check]]
id = "a_check"
points = 3

[[check]]
id = "another_check"
points = 1
uses = [1]
)toml";

const std::string kLab1 = "number = 1\nid = \"lab1_first\"\ntitle = { en = \"First\", fr = \"Premier\" }\n";

} // namespace

TEST_SUITE("lab descriptions") {

TEST_CASE("a lab's items, points, titles and the labs it uses") {
    const Course course;
    course.scene("lab2_picture");
    course.lab("lab1_first", kLab1);
    course.lab("lab2_rays", kLab2);
    const LabCatalog catalog = course.load();
    REQUIRE(catalog.numbers() == std::vector<int>{1, 2});
    const LabDescription& lab = *catalog.lab(2);
    CHECK(lab.title("fr") == "Rayons");
    CHECK(lab.uses == std::vector<int>{1});
    REQUIRE(lab.functions.size() == 1);
    CHECK(lab.functions[0].name == "trace");
    CHECK(catalog.figure("lab2_picture")->handout == "2(b)");
    CHECK(catalog.figure("lab2_picture")->caption("en") == "A picture");
    CHECK(catalog.figure("lab2_picture")->uses == std::vector<int>{1}); // the lab's, unless it says
    CHECK(catalog.labOfFigure("lab2_picture") == &lab);
    CHECK(catalog.figurePoints("lab2_picture", 7.) == 1.5);
    CHECK(catalog.checkPoints(2, "a_check") == 3.);
    CHECK_THROWS_AS(catalog.checkPoints(2, "unknown"), std::logic_error); // no silent default
    CHECK_THROWS_AS(catalog.checkPoints(1, "a_check"), std::logic_error);
    CHECK(lab.check("a_check")->uses.empty()); // a check runs its own lab's code unless it says
    CHECK(lab.check("another_check")->uses == std::vector<int>{1});
}

TEST_CASE("a figure's lab is the lab.toml that lists it: the scenes in the order of their lab") {
    const Course course;
    for (const char* id : {"lab2_picture", "z_first_lab", "a_no_lab"}) course.scene(id);
    course.lab("lab1_first", kLab1 + "[[figure]]\nid = \"z_first_lab\"\nscene = \"z_first_lab.toml\"\nhandout = \"1\"\n"
                                     "caption = { en = \"Z\", fr = \"Z\" }\npoints = 1\n");
    course.lab("lab2_rays", kLab2);
    const LabCatalog catalog = course.load();
    CHECK(catalog.labNumberOfFigure("z_first_lab") == 1);
    CHECK(catalog.labNumberOfFigure("lab2_picture") == 2);
    CHECK(catalog.labNumberOfFigure("a_no_lab") == 0);
    std::vector<std::string> ids;
    for (const raylab::SceneDescription& d : loadFiguresInLabOrder(course.root / "scenes", catalog)) ids.push_back(d.id);
    CHECK(ids == std::vector<std::string>{"a_no_lab", "z_first_lab", "lab2_picture"});
}

TEST_CASE("a bad description is refused, naming the file, the line and the key") {
    const Course course;
    course.scene("lab2_picture");
    course.lab("lab1_first", kLab1);
    const auto refused = [&](const std::string& text, const std::string& expected) {
        const fs::path file = course.lab("lab2_rays", text);
        CHECK_THROWS_WITH_AS(course.load(), doctest::Contains(expected.c_str()), std::runtime_error);
        CHECK_THROWS_WITH_AS(course.load(), doctest::Contains(file.string().c_str()), std::runtime_error);
    };
    const auto replaced = [](std::string text, const std::string& from, const std::string& to) {
        return text.replace(text.find(from), from.size(), to);
    };
    refused(replaced(kLab2, "points = 3", "points = -1"), ":19: [[check]] #1 points: points must be a number >= 0");
    refused(replaced(kLab2, "points = 1.5", "points = \"two\""), ":15: [[figure]] #1 points: expected a number, got a string");
    refused(replaced(kLab2, "points = 1.5", "points = nan"), ":15: [[figure]] #1 points: must be finite, got nan");
    refused(replaced(kLab2, "uses = [1]\n\n[[function]]", "uses = [1, 3]\n\n[[function]]"), "uses: there is no lab 3");
    refused(replaced(kLab2, "points = 1\nuses = [1]", "points = 1\nuses = [4]"), ":24: [[check]] #2 uses: lab 4 is not in the lab's uses");
    refused(replaced(kLab2, "id = \"lab2_rays\"", "id = \"lab2_other\""), ":2: id: \"lab2_other\" is not the folder's name");
    refused(replaced(kLab2, "number = 2", "number = 3"),
            "lab.toml:1: number: 3 is not the number of the lab's folder, lab2_rays (a lab's folder is lab<number>_<name>)");
    refused(replaced(kLab2, "handout = \"2(b)\"", "hand_out = \"2(b)\""), ":13: [[figure]] #1 hand_out: unknown key");
    refused(replaced(kLab2, "lab2_picture.toml", "lab2_missing.toml"), "[[figure]] #1 scene: expected lab2_picture.toml");
    refused(replaced(kLab2, "file = \"code.cpp\"", "file = \"gone.cpp\""), ":7: [[function]] #1 file: no file gone.cpp");
    refused(replaced(kLab2, "file = \"code.cpp\"", "file = \"x;y.cpp\""),
            ":7: [[function]] #1 file: \"x;y.cpp\" is not a plain file name");
    refused(replaced(kLab2, "file = \"code.cpp\"", "file = \"../lab1_first/code.cpp\""), "is not a plain file name");
    refused(replaced(kLab2, "file = \"code.cpp\"", "file = \"lab.toml\""), "is not a plain file name");
    refused(replaced(kLab2, ", fr = \"Rayons\" }", " }"), "title.fr: missing");
    refused(replaced(kLab2, "[[check]]\nid = \"another_check\"", "[[check]]\nid = \"a_check\""),
            "check: the id \"a_check\" is there twice");
    // An id keys a message, a command's argument and a workflow step: a sentence is its title, not its id.
    refused(replaced(kLab2, "id = \"a_check\"", "id = \"trace: a check\""),
            ":18: [[check]] #1 id: \"trace: a check\": a check's id is 1 to 40 lower-case letters, digits and _, from a letter");
    refused(replaced(kLab2, "id = \"a_check\"", "id = \"A_check\""), ":18: [[check]] #1 id: \"A_check\"");
    refused(replaced(kLab2, "id = \"a_check\"", "id = \"\""), ":18: [[check]] #1 id: expected a non-empty string");
    refused(replaced(kLab2, "id = \"a_check\"", "name = \"a_check\""), ":18: [[check]] #1 name: unknown key (known keys: id, points, uses)");
    // Unique in the course: another lab's check or figure of that id is refused, naming both.
    course.lab("lab1_first", kLab1 + "\n[[check]]\nid = \"a_check\"\npoints = 1\n");
    refused(kLab2, "lab.toml:17: check: a_check is also a check or a figure of "); // its [[check]]'s line
    refused(replaced(kLab2, "id = \"a_check\"", "id = \"lab2_picture\""), "check: the id \"lab2_picture\" is there twice");
    course.lab("lab1_first", kLab1 + "\n[[check]]\nid = \"lab2_picture\"\npoints = 1\n");
    refused(kLab2, "check: lab2_picture is also a check or a figure of ");
    course.lab("lab1_first", kLab1);
    refused(replaced(kLab2, "number = 2\n", "number = 2\n[oops\n"), "lab.toml:2:6: not valid TOML: ");
    course.lab("lab2_rays", kLab2);
    course.lab("lab1_again", replaced(kLab1, "lab1_first", "lab1_again"));
    CHECK_THROWS_WITH_AS(course.load(), doctest::Contains("number: 1 is also the number of"), std::runtime_error);
}

TEST_CASE("a lab's number and id are those of its folder's name, lab<N>_<name>, which CMake reads") {
    const Course course;
    course.scene("lab2_picture");
    course.lab("lab1_first", kLab1); // lab 2 uses it: the folder's name is the only problem
    for (const char* folder : {"lab02_rays", "lab-2_rays", "lab_rays", "lab2_"}) {
        std::string text = kLab2;
        text.replace(text.find("lab2_rays"), 9, folder);
        const fs::path file = course.lab(folder, text);
        CHECK_THROWS_WITH_AS(course.load(),
                             (file.string() + ":2: id: the folder " + folder +
                              " is not named lab<number>_<name>, the number without a leading zero").c_str(),
                             std::runtime_error);
        fs::remove_all(file.parent_path());
    }
}

TEST_CASE("a lab's files: each declared once, in order, and no two labs share a file's name") {
    const Course course;
    course.scene("lab2_picture");
    course.lab("lab1_first", kLab1 + "[[function]]\nfile = \"code.cpp\"\nname = \"first\"\n");
    course.lab("lab2_rays", kLab2 + "[[function]]\nfile = \"code.cpp\"\nname = \"again\"\n");
    // A file uploaded without its folder goes to its lab by its name: two labs cannot both own it.
    CHECK_THROWS_WITH_AS(course.load(), doctest::Contains("file code.cpp is also a file of"), std::runtime_error);
    course.lab("lab1_first", kLab1);
    const LabCatalog catalog = course.load();
    CHECK(catalog.lab(2)->files() == std::vector<std::string>{"code.cpp"});
    CHECK(catalog.lab(1)->files().empty());
    const LabCatalog real = loadLabCatalog(fs::path(RAYLAB_SOURCE_DIR) / "labs");
    CHECK(real.lab(3)->files() == std::vector<std::string>{"sphere_geometry.cpp", "ray_cast_integrator.cpp"});
}

TEST_CASE("a lab the course leaves out is given when the framework calls its functions, else absent") {
    const Course course;
    course.scene("lab2_picture");
    course.lab("lab1_first", kLab1 + "framework_calls = true\n");
    course.lab("lab2_rays", kLab2);
    std::ofstream(course.root / "course.toml") << "labs = [2]\n";
    const LabCatalog catalog = course.load();
    CHECK(catalog.numbers() == std::vector<int>{2});
    REQUIRE(catalog.given.size() == 1);
    CHECK(catalog.given[0].number == 1);
    CHECK(catalog.given[0].frameworkCalls);
    CHECK(catalog.lab(1) == nullptr); // not graded
    CHECK(catalog.lab(2)->uses.empty()); // the given lab is the framework's
    CHECK(catalog.figure("lab2_picture")->uses.empty());
    CHECK(catalog.lab(2)->check("another_check")->uses.empty());
    CHECK_FALSE(catalog.lab(2)->frameworkCalls);

    course.lab("lab1_first", kLab1); // its own functions only: left out, it is absent, and lab 2 cannot use it
    CHECK_THROWS_WITH_AS(course.load(), doctest::Contains("uses: there is no lab 1"), std::runtime_error);
    course.lab("lab1_first", kLab1 + "framework_calls = \"yes\"\n");
    CHECK_THROWS_WITH_AS(course.load(), doctest::Contains("lab.toml:4: framework_calls: expected true or false"), std::runtime_error);
    std::ofstream(course.root / "course.toml") << "labs = [1, 2]\n";
    course.lab("lab1_first", kLab1 + "framework_calls = true\n");
    CHECK(course.load().given.empty()); // handed out: graded as any lab

    // A students' tree: no lab.toml of the given lab, its reference in framework/given/<lab>/.
    fs::remove_all(course.root / "labs" / "lab1_first");
    fs::create_directories(course.root / "framework" / "given" / "lab1_first");
    std::ofstream(course.root / "course.toml") << "labs = [2]\n";
    const LabCatalog students = course.load();
    CHECK(students.numbers() == std::vector<int>{2});
    REQUIRE(students.given.size() == 1);
    CHECK(students.given[0].number == 1);
    CHECK(students.given[0].id == "lab1_first");
    CHECK(students.lab(2)->uses.empty());
}

TEST_CASE("a lab's kinds of objects and lights: C++ class names, declared in the shapes.h and lights.h beside its lab.toml") {
    const Course course;
    course.scene("lab2_picture");
    course.lab("lab2_rays", kLab2);
    const fs::path file = course.lab("lab1_first", kLab1 + "shapes = [\"Triangle\"]\n");
    CHECK_THROWS_WITH_AS(course.load(), (file.string() + ":4: shapes: no shapes.h beside lab.toml to declare them").c_str(),
                         std::runtime_error);
    std::ofstream(file.parent_path() / "shapes.h") << "#pragma once\n";
    CHECK(course.load().lab(1) != nullptr);
    course.lab("lab1_first", kLab1 + "shapes = [\"Triangle\", \"3d_box\"]\n");
    CHECK_THROWS_WITH_AS(course.load(), (file.string() + ":4: shapes: \"3d_box\" is not the name of a C++ class").c_str(),
                         std::runtime_error);
    course.lab("lab1_first", kLab1 + "shapes = [\"Triangle\", 3]\n");
    CHECK_THROWS_WITH_AS(course.load(), doctest::Contains("lab.toml:4: shapes"), std::runtime_error);
    // Lights the same way, in their own header: shapes.h does not declare them.
    course.lab("lab1_first", kLab1 + "shapes = [\"Triangle\"]\nlights = [\"AreaLight\"]\n");
    CHECK_THROWS_WITH_AS(course.load(), (file.string() + ":5: lights: no lights.h beside lab.toml to declare them").c_str(),
                         std::runtime_error);
    std::ofstream(file.parent_path() / "lights.h") << "#pragma once\n";
    CHECK(course.load().lab(1) != nullptr);
    course.lab("lab1_first", kLab1 + "lights = [\"Area-Light\"]\n");
    CHECK_THROWS_WITH_AS(course.load(), (file.string() + ":4: lights: \"Area-Light\" is not the name of a C++ class").c_str(),
                         std::runtime_error);
}

TEST_CASE("the course's descriptions agree with the references and the scene files") {
    const LabCatalog catalog = loadLabCatalog(fs::path(RAYLAB_SOURCE_DIR) / "labs");
    std::vector<fs::path> folders;
    for (const LabDescription& lab : catalog.labs) folders.push_back(fs::path(RAYLAB_SOURCE_DIR) / "framework/grader/labs" / lab.id / "references");
    const ReferenceSet references = loadReferences(folders);
    REQUIRE_FALSE(catalog.labs.empty());
    std::size_t figures = 0;
    for (const LabDescription& lab : catalog.labs) {
        CAPTURE(lab.file);
        CHECK(lab.checks.size() >= 3);
        CHECK(lab.figures.size() >= 1);
        CHECK(lab.functions.size() >= 1);
        for (const LabFigure& f : lab.figures) {
            const FigureReference* reference = references.find(f.id);
            CHECK_MESSAGE(reference != nullptr, f.id << " has no reference (raylab references)");
            if (reference != nullptr) CHECK_MESSAGE(reference->lab == lab.number, f.id);
        }
        figures += lab.figures.size();
    }
    CHECK(figures == references.figures.size());
}

} // TEST_SUITE

TEST_CASE(
    "a check of the code lab.toml does not name, or one of lab.toml with no code, is an error naming both places") {
    const LabCatalog real = loadLabCatalog(fs::path(RAYLAB_SOURCE_DIR) / "labs");
    LabDescription lab = *real.lab(3);
    CaseRandom random(1);
    const std::vector<FunctionCheck> checks = labChecks(lab, random);
    REQUIRE(checks.size() == lab.checks.size());
    CHECK(checks[0].points == lab.checks[0].points); // the points are lab.toml's
    CHECK(checks[0].lab == 3);

    // Renamed in lab.toml only: the code's check is in no lab.toml, lab.toml's has no code.
    const std::string code = checks[0].id, file = lab.file.string(), line = std::to_string(lab.checks[0].line);
    lab.checks[0].id = "intersect: renamed in lab.toml";
    CHECK(lab.checks[0].line > 10);
    try {
        labChecks(lab, random);
        FAIL("a renamed check was accepted");
    } catch (const std::runtime_error& e) {
        const std::string message = e.what();
        CHECK_MESSAGE(message.find("framework/grader/labs/lab3_sphere/checks.cpp:") != std::string::npos, message);
        CHECK_MESSAGE(message.find("the check \"" + code + "\" is not in " + file) != std::string::npos, message);
        CHECK_MESSAGE(message.find(file + ":" + line +
                                   ": the check \"renamed_in_lab_toml\" has no code: "
                                   "framework/grader/labs/lab3_sphere/checks.cpp:") != std::string::npos,
                      message);
    }

    // A lab with checks whose grading folder registers none; and a registered lab no lab.toml describes.
    lab = *real.lab(3);
    lab.id = "lab3_elsewhere";
    CHECK_THROWS_WITH_AS(labChecks(lab, random),
                         doctest::Contains("no grading folder registers the checks of lab3_elsewhere"),
                         std::runtime_error);
    LabCatalog without = real;
    without.labs.erase(without.labs.begin() + 2);
    CHECK_THROWS_WITH_AS(functionChecks(without, 1), doctest::Contains("lab3_sphere/checks.cpp:"), std::runtime_error);
}
