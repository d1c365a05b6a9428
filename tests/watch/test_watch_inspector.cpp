// The pixel inspector against agents of known code (built by tests/grading from solutions/ and the
// mistakes' patches): the reference's own agent agrees on every value of a pixel of labs 1 to 5; a
// mirrored lookAt basis (mistake M4.1) differs first at the camera's u, and the rows after it say they
// follow the reference's ray; the same sample offset for every sample (lab 5) first at the second
// sample; lab 6's shadow rays, and a shadow ray cast away from the light first at what it meets. Run under each sandbox (ctest's RAYLAB_SANDBOX). The
// pixels are those of the course's labs; a lab's own cases, a suite each, are skipped where the course
// does not hand it out (support/course.h).
#include "watch/pixel_inspector.h"

#include "grader/lab_catalog.h"
#include "src/messages.h"
#include "support/course.h"
#include "support/files.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The inspector's answer for a pixel, `program` standing as the students' tree's one agent. The
// folder is the sandbox's own: ctest runs the suite under each sandbox at once.
json inspect(const std::string& program, const std::string& figure, int x, int y) {
    const char* sandbox = std::getenv("RAYLAB_SANDBOX");
    const fs::path bin = raylab::test::freshFolder("watch-inspector-" + std::string(sandbox ? sandbox : "any") + "-" + program);
    fs::copy_file(fs::path(RAYLAB_BIN_DIR) / program, bin / "raylab-agent");
    raylab::watch::WatchSettings settings;
    settings.binDir = bin;
    settings.out = bin / "out";
    const raylab::grader::LabCatalog labs = raylab::grader::loadLabCatalog(fs::path(RAYLAB_SOURCE_DIR) / "labs"); // each lab's scenes
    for (const raylab::grader::LabDescription& lab : labs.labs) // the grader's references, as raylab watch has them
        settings.references.push_back(fs::path(RAYLAB_SOURCE_DIR) / "framework/grader/labs" / lab.id / "references");
    std::mutex agents;
    const raylab::watch::PixelInspector inspector(settings, labs, agents);
    return json::parse(inspector.inspect(figure, x, y));
}

// The anchor GitHub gives a Markdown heading: lower case, spaces as '-', punctuation dropped (the
// letters beyond ASCII kept as they are).
std::string anchorOf(const std::string& heading) {
    std::string anchor;
    for (const char c : heading) {
        const auto byte = static_cast<unsigned char>(c);
        if (std::isalnum(byte) || c == '-' || c == '_' || byte >= 0x80) anchor += char(std::tolower(byte));
        else if (c == ' ') anchor += '-';
    }
    return anchor;
}

// Whether "labs/<lab>/README.md#anchor" names a heading of that handout.
bool handoutSectionExists(const std::string& link) {
    const std::size_t hash = link.find('#');
    std::istringstream text(raylab::test::readFile(fs::path(RAYLAB_SOURCE_DIR) / link.substr(0, hash)));
    for (std::string line; std::getline(text, line);)
        if (line.starts_with("#") && anchorOf(line.substr(line.find_first_not_of('#') + 1)) == link.substr(hash + 1)) return true;
    return false;
}

struct Pixel {
    std::string figure;
    int x, y;
};

// The pixels of `pixels` whose figure is of a lab of the course.
std::vector<Pixel> inCourse(const std::vector<Pixel>& pixels) {
    const raylab::grader::LabCatalog labs = raylab::grader::loadLabCatalog(fs::path(RAYLAB_SOURCE_DIR) / "labs");
    std::vector<Pixel> kept;
    for (const Pixel& p : pixels)
        if (labs.labNumberOfFigure(p.figure) != 0) kept.push_back(p);
    REQUIRE_MESSAGE(!kept.empty(), "no pixel of a lab of this course");
    return kept;
}

bool labInCourse(int number) { return raylab::test::labInCourse(fs::path(RAYLAB_SOURCE_DIR) / "labs", number); }

std::vector<std::string> names(const json& answer) {
    std::vector<std::string> all;
    for (const json& row : answer["rows"]) all.push_back(row["name"]);
    return all;
}

// A row of the answer by its name; null when there is none.
json row(const json& answer, const std::string& name) {
    for (const json& r : answer["rows"])
        if (r["name"] == name) return r;
    return {};
}

} // namespace

TEST_SUITE("watch inspector") {

TEST_CASE("the reference's agent agrees with the reference on every value") {
    for (const auto& [figure, x, y] : inCourse({{"lab1_gradient", 450, 100}, {"lab2_directions", 10, 390}, {"lab3_cosine", 300, 150},
                                                {"lab3_placeholder_normal", 250, 180}, {"lab4_d", 150, 100},
                                                {"lab5_antialiased", 300, 100}})) {
        const json answer = inspect("raylab-agent-reference", figure, x, y);
        INFO(answer.dump(1));
        CHECK(answer["note"] == "");
        CHECK(answer["first"] == -1);
        CHECK(answer["rows"].size() >= 2);
        for (const json& row : answer["rows"]) // but the pictures' pixel: nothing was graded into settings.out here
            if (row["name"] != "pixel colour") CHECK(!row["student"].is_null());
    }
}

TEST_CASE("a pixel outside the picture, a figure of no lab: said, nothing run") {
    CHECK(inspect("raylab-agent-reference", "lab3_cosine", 600, 0)["note"] == "pixel (600, 0) is outside the picture (600 x 400)");
    CHECK(inspect("raylab-agent-reference", "../secret", 1, 1)["note"] == "no figure ../secret in this lab");
    CHECK(inspect("raylab-agent-reference", "lab1_gradient", 600, 399)["rows"].empty());
}

TEST_CASE("lab 1: the colour fillGradient writes at a pixel, beside the reference picture's, in 8 bits") {
    if (!labInCourse(1)) return;
    const json agreed = inspect("raylab-agent-reference", "lab1_gradient", 450, 100);
    INFO(agreed.dump(1));
    REQUIRE(names(agreed) == std::vector<std::string>{"pixel (i, j) of a W x H image", "colour written at (i, j)"});
    CHECK(agreed["note"] == "");
    CHECK(agreed["first"] == -1);
    CHECK(agreed["rows"][0]["reference"] == json::array({450, 100, 600, 400}));
    // The reference picture's bytes: red 450 / 599, green 100 / 399, blue 0, each rounded to 8 bits.
    CHECK(agreed["rows"][1]["reference"] == json::array({192 / 255., 64 / 255., 0.}));
    CHECK(agreed["rows"][1]["student"][0].get<double>() == doctest::Approx(450. / 599.).epsilon(1e-6));
    // i and j swapped (mistake M1): red 100 / 399 where the reference has 450 / 599.
    const json swapped = inspect("raylab-mistake-i_j_swapped", "lab1_gradient", 450, 100);
    INFO(swapped.dump(1));
    CHECK(swapped["first"] == 1);
    CHECK(swapped["rows"][1]["student"][0].get<double>() == doctest::Approx(100. / 399.).epsilon(1e-6));
    // On the diagonal where i / (W - 1) = j / (H - 1) the swap is not seen: nothing differs.
    CHECK(inspect("raylab-mistake-i_j_swapped", "lab1_gradient", 0, 0)["first"] == -1);
}

TEST_CASE("a row the student's code computed on the reference's ray says so, only after the ray differs") {
    for (const auto& [figure, x, y] : inCourse({{"lab3_cosine", 300, 150}, {"lab4_d", 150, 100}})) {
        const json answer = inspect("raylab-agent-reference", figure, x, y);
        for (const json& row : answer["rows"]) CHECK_MESSAGE(row["follows"] == "", row["name"]); // nothing differs
    }
}

TEST_CASE("every row links a section of its handout, in English and in French") {
    for (const raylab::Language language : {raylab::Language::En, raylab::Language::Fr}) {
        raylab::setLanguage(language);
        for (const auto& [figure, x, y] : inCourse({{"lab3_cosine", 300, 150}, {"lab4_d", 150, 100}, {"lab5_antialiased", 300, 100}})) {
            const json answer = inspect("raylab-agent-reference", figure, x, y); // kept: the loop reads inside it
            for (const json& row : answer["rows"]) CHECK_MESSAGE(handoutSectionExists(row["handout"]), row["handout"]);
        }
    }
    CHECK(inspect("raylab-agent-reference", "lab3_cosine", 300, 150)["rows"][6]["name"] == "normale");
    raylab::setLanguage(raylab::Language::En);
}

TEST_CASE("the far root first: t differs first, and the normal after it says it is at the reference's hit point") {
    if (!labInCourse(3)) return;
    const json answer = inspect("raylab-mistake-far_root_first", "lab3_cosine", 300, 150);
    INFO(answer.dump(1));
    REQUIRE(answer["first"] == 4);
    CHECK(answer["rows"][4]["name"] == "t");
    CHECK(answer["rows"][3]["follows"] == ""); // hit: on the student's own ray, which is the reference's
    CHECK(answer["rows"][6]["name"] == "normal");
    CHECK(answer["rows"][6]["follows"] == "from here on: the reference's hit point, not yours (your code's answer on it)");
    CHECK(answer["rows"][7]["name"] == "colour");
    CHECK(answer["rows"][7]["follows"] == ""); // Li takes the ray only, the student's own
}

} // TEST_SUITE

TEST_SUITE("watch inspector: lab 4") {

TEST_CASE("the rows of a lab 4 pixel") {
    if (!labInCourse(4)) return;
    CHECK(names(inspect("raylab-agent-reference", "lab4_d", 150, 100)) ==
          std::vector<std::string>{"(sx, sy)", "camera u", "camera v", "camera w", "topLeft", "hit", "t", "hit position",
                                   "normal", "colour"});
}

TEST_CASE("a mirrored lookAt basis differs first at u, with its formula") {
    if (!labInCourse(4)) return;
    const json answer = inspect("raylab-mistake-mirrored_basis", "lab4_d", 150, 100);
    INFO(answer.dump(1));
    REQUIRE(answer["first"] == 1);
    CHECK(answer["rows"][1]["name"] == "camera u");
    CHECK(answer["rows"][1]["formula"] == "u = normalize(cross(up, w))");
    CHECK(answer["rows"][1]["handout"] == "labs/lab4_lookat_camera/README.md#the-maths");
    // The camera's rows are the student's own; every row after them is their code on the reference's
    // ray, and says so (the colour under "yours" is not their pixel's).
    for (std::size_t k = 0; k < 5; ++k) CHECK_MESSAGE(answer["rows"][k]["follows"] == "", answer["rows"][k]["name"]);
    REQUIRE(answer["rows"].size() > 5);
    for (std::size_t k = 5; k < answer["rows"].size(); ++k)
        CHECK_MESSAGE(answer["rows"][k]["follows"] == "from here on: the reference's ray, not yours (your code's answer on it)",
                      answer["rows"][k]["name"]);
    raylab::setLanguage(raylab::Language::Fr);
    const json french = inspect("raylab-mistake-mirrored_basis", "lab4_d", 150, 100);
    raylab::setLanguage(raylab::Language::En);
    CHECK(french["rows"][5]["follows"].get<std::string>().starts_with("à partir d'ici\u00A0: le rayon de la référence, pas le vôtre"));
}

} // TEST_SUITE

TEST_SUITE("watch inspector: lab 5") {

TEST_CASE("one offset for every sample differs first at the second sample") {
    if (!labInCourse(5)) return;
    const json answer = inspect("raylab-mistake-same_offset_every_sample", "lab5_antialiased", 300, 100);
    INFO(answer.dump(1));
    CHECK(answer["rows"][0]["name"] == "samples traced");
    CHECK(answer["rows"][0]["differs"] == false);
    REQUIRE(answer["first"] == 2);
    CHECK(answer["rows"][2]["name"] == "sample 2 (sx, sy)");
}

} // TEST_SUITE

TEST_SUITE("watch inspector: lab 6") {

// lab6_shadows (600 x 400): the ground in the big sphere's shadow, the top of the big sphere facing
// the light, the ground far from both spheres.
constexpr int kShadowX = 233, kShadowY = 237, kSphereTopX = 332, kSphereTopY = 138, kGroundX = 496, kGroundY = 298;

TEST_CASE("the shadow ray, the light it tests, what it meets and Lambert's term, all agreed by the reference's agent") {
    if (!labInCourse(6)) return;
    const json shadow = inspect("raylab-agent-reference", "lab6_shadows", kShadowX, kShadowY);
    INFO(shadow.dump(1));
    CHECK(shadow["note"] == "");
    CHECK(shadow["first"] == -1);
    CHECK(row(shadow, "camera u")["differs"] == false); // lab 4's camera first
    CHECK(row(shadow, "the object the ray hits first")["reference"] == "plane 1");
    CHECK(row(shadow, "light 1: its position")["reference"] == json::array({-3., 6., 4.}));
    const json origin = row(shadow, "light 1: shadow ray origin"), direction = row(shadow, "light 1: shadow ray direction");
    CHECK(origin["reference_only"] == true);
    CHECK(origin["student"].is_null()); // no function of the lab hands it back: never shown as the student's
    CHECK(std::abs(origin["reference"][1].get<double>()) < 1e-6); // on the ground
    CHECK(direction["reference"][1].get<double>() > 0.); // up, towards the light
    CHECK(row(shadow, "light 1: what the shadow ray meets")["reference"] == "sphere 1");
    CHECK(row(shadow, "light 1: what the shadow ray meets")["student"] == "sphere 1");
    CHECK(row(shadow, "light 1: t of the nearest object it meets")["reference"].get<double>() > 0.);
    CHECK(row(shadow, "light 1: in shadow (not lit)")["reference"] == true);
    CHECK(row(shadow, "light 1: in shadow (not lit)")["student"] == true);
    CHECK(!row(shadow, "light 1: Lambert's term")["student"].is_null());
    CHECK(row(shadow, "light 1: Lambert's term")["differs"] == false);
    for (const json& r : shadow["rows"])
        if (r["reference_only"] == true) CHECK_MESSAGE(r["differs"] == false, r["name"]);

    const json ground = inspect("raylab-agent-reference", "lab6_shadows", kGroundX, kGroundY);
    INFO(ground.dump(1));
    CHECK(ground["first"] == -1);
    CHECK(row(ground, "light 1: what the shadow ray meets")["reference"] == "none");
    CHECK(row(ground, "light 1: in shadow (not lit)")["student"] == false);
    CHECK(row(ground, "light 1: t of the nearest object it meets").is_null());

    // Without the shadow test: no shadow ray, Lambert's term still.
    const json plain = inspect("raylab-agent-reference", "lab6_no_shadows", kShadowX, kShadowY);
    CHECK(plain["first"] == -1);
    CHECK(row(plain, "light 1: shadow ray origin").is_null());
    CHECK(!row(plain, "light 1: Lambert's term").is_null());
}

TEST_CASE("a shadow ray cast away from the light: the first row that differs is what it meets") {
    if (!labInCourse(6)) return;
    const json answer = inspect("raylab-mistake-light_direction_reversed", "lab6_shadows", kSphereTopX, kSphereTopY);
    INFO(answer.dump(1));
    REQUIRE(answer["first"].get<int>() >= 0);
    const json first = answer["rows"][answer["first"].get<std::size_t>()];
    CHECK(first["name"] == "light 1: what the shadow ray meets");
    CHECK(first["function"] == "inShadow");
    CHECK(first["reference"] == "none");
    CHECK(first["student"].get<std::string>().starts_with("sphere 1")); // into the sphere it leaves (and on, down to the ground)
    CHECK(row(answer, "light 1: in shadow (not lit)")["student"] == true);
    CHECK(row(answer, "light 1: in shadow (not lit)")["differs"] == true);
    CHECK(row(answer, "light 1: Lambert's term")["differs"] == false); // Li without the shadow test is right
}

TEST_CASE("every lab 6 row links a section of its handout, in English and in French") {
    if (!labInCourse(6)) return;
    for (const raylab::Language language : {raylab::Language::En, raylab::Language::Fr}) {
        raylab::setLanguage(language);
        const json answer = inspect("raylab-agent-reference", "lab6_shadows", kShadowX, kShadowY);
        for (const json& r : answer["rows"]) CHECK_MESSAGE(handoutSectionExists(r["handout"]), r["handout"]);
    }
    raylab::setLanguage(raylab::Language::En);
}

} // TEST_SUITE

TEST_SUITE("watch inspector: lab 7") {

// lab7_quad (600 x 400): the lower right half of the square, triangle 1's (red); lab7_tetrahedron:
// a face of the tetrahedron turned to the camera.
constexpr int kQuadX = 380, kQuadY = 280, kTetrahedronX = 392, kTetrahedronY = 205;

TEST_CASE("each triangle crossed or not, the nearest one's t, hit point and normal, agreed by the reference's agent") {
    if (!labInCourse(7)) return;
    const json quad = inspect("raylab-agent-reference", "lab7_quad", kQuadX, kQuadY);
    INFO(quad.dump(1));
    CHECK(quad["note"] == "");
    CHECK(quad["first"] == -1);
    CHECK(row(quad, "triangle 1: crossed")["reference"] == true);
    CHECK(row(quad, "triangle 2: crossed")["reference"] == false);
    CHECK(row(quad, "the nearest triangle crossed")["reference"] == 1);
    CHECK(row(quad, "its t")["student"].get<double>() == doctest::Approx(row(quad, "its t")["reference"].get<double>()));
    const json tetrahedron = inspect("raylab-agent-reference", "lab7_tetrahedron", kTetrahedronX, kTetrahedronY);
    INFO(tetrahedron.dump(1));
    CHECK(tetrahedron["first"] == -1);
    CHECK(row(tetrahedron, "triangle 4: crossed").is_object());
    CHECK(!row(tetrahedron, "its normal")["student"].is_null());
}

TEST_CASE("no u + v <= 1: the first row that differs is the other triangle, crossed where it is not") {
    if (!labInCourse(7)) return;
    const json answer = inspect("raylab-mistake-no_u_plus_v", "lab7_quad", kQuadX, kQuadY);
    INFO(answer.dump(1));
    REQUIRE(answer["first"].get<int>() >= 0);
    const json first = answer["rows"][answer["first"].get<std::size_t>()];
    CHECK(first["name"] == "triangle 2: crossed");
    CHECK(first["function"] == "Triangle::intersect");
    CHECK(first["student"] == true);
}

TEST_CASE("the normal flipped: the first row that differs is the normal, the opposite of the reference's") {
    if (!labInCourse(7)) return;
    const json answer = inspect("raylab-mistake-normal_flipped", "lab7_tetrahedron", kTetrahedronX, kTetrahedronY);
    INFO(answer.dump(1));
    REQUIRE(answer["first"].get<int>() >= 0);
    const json first = answer["rows"][answer["first"].get<std::size_t>()];
    CHECK(first["name"] == "its normal");
    for (std::size_t k = 0; k < 3; ++k) CHECK(first["student"][k].get<double>() == doctest::Approx(-first["reference"][k].get<double>()));
}

TEST_CASE("every lab 7 row links a section of its handout, in English and in French") {
    if (!labInCourse(7)) return;
    for (const raylab::Language language : {raylab::Language::En, raylab::Language::Fr}) {
        raylab::setLanguage(language);
        const json answer = inspect("raylab-agent-reference", "lab7_tetrahedron", kTetrahedronX, kTetrahedronY);
        REQUIRE(answer["rows"].size() > 4);
        for (const json& r : answer["rows"]) CHECK_MESSAGE(handoutSectionExists(r["handout"]), r["handout"]);
    }
    raylab::setLanguage(raylab::Language::En);
}

} // TEST_SUITE
