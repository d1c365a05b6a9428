// The grading protocol: messages survive the trip and bad ones are refused with a reason; the
// parent judges, so forged answers, answers learnt by heart and pictures rewritten after the
// render earn nothing.
#include "grading_support.h"
#include "support/course.h"

#include "grader/judge/checks/checks.h"
#include "grader/protocol/protocol.h"

#include <chrono>
#include <cmath>
#include <cstdlib>

using namespace raylab::test;
namespace protocol = raylab::grader::protocol;

namespace {

protocol::Answer roundTrip(const protocol::Answer& answer) {
    const protocol::Parsed<protocol::Answer> parsed = protocol::parseAnswer(protocol::serialize(answer));
    REQUIRE_MESSAGE(parsed.message, parsed.error);
    return *parsed.message;
}

std::string refusal(const std::string& line) {
    const protocol::Parsed<protocol::Answer> parsed = protocol::parseAnswer(line);
    CHECK_FALSE(parsed.message);
    return parsed.error;
}

void expectLabPoints(const GradeResult& r, int lab, double points) {
    const LabOutcome& outcome = r.labs.at(std::size_t(lab - 1));
    CHECK_MESSAGE(outcome.points == points,
                  "lab " << lab << ": " << outcome.points << " / " << outcome.maxPoints << failures(r));
}

} // namespace

TEST_SUITE("protocol") {

    TEST_CASE("every message survives serialization, NaN and infinities as values") {
        const double nan = std::nan("");
        const auto values = std::get<protocol::Values>(roundTrip(protocol::Values{7, {{1.5, nan, -INFINITY}, {}}}));
        CHECK(values.item == 7);
        REQUIRE(values.outputs.size() == 2);
        CHECK(values.outputs[0][0] == 1.5);
        CHECK(std::isnan(values.outputs[0][1]));
        CHECK(values.outputs[0][2] == -INFINITY);
        const auto todo = std::get<protocol::NotDone>(
            roundTrip(protocol::NotDone{3, "lab 2", "PerspectiveCamera::generateRay", "a.cpp", 12}));
        CHECK(todo.function == "PerspectiveCamera::generateRay");
        CHECK(todo.line == 12);
        CHECK(std::get<protocol::Failure>(roundTrip(protocol::Failure{4, "bad \"quoted\"\nline"})).message ==
              "bad \"quoted\"\nline");
        CHECK(std::get<protocol::Hello>(roundTrip(protocol::Hello{protocol::kVersion})).version == protocol::kVersion);
        CHECK(std::holds_alternative<protocol::Done>(roundTrip(protocol::Done{})));

        const protocol::Request request = protocol::CheckRequest{
            9, {{protocol::probeNamed("intersect"), {0, 0, 3, 1, 0, 0, 0, 0, 0, 1, 0, INFINITY}}}, 3};
        const protocol::Parsed<protocol::Request> parsed = protocol::parseRequest(protocol::serialize(request));
        REQUIRE(parsed.message);
        const auto& check = std::get<protocol::CheckRequest>(*parsed.message);
        CHECK(check.calls.at(0).probe ==
              protocol::probeNamed("intersect")); // lab 3's, registered by its grading folder
        CHECK(check.calls.at(0).inputs.back() == INFINITY);
        CHECK(check.lab == 3);
    }

    TEST_CASE("a 600 x 400 picture travels whole and fast") {
        protocol::Picture picture{1, 600, 400, std::vector<std::uint8_t>(600 * 400 * 3)};
        for (std::size_t k = 0; k < picture.rgb.size(); ++k)
            picture.rgb[k] = std::uint8_t(k * 7919 % 251);
        const auto start = std::chrono::steady_clock::now();
        const std::string line = protocol::serialize(picture);
        const auto back = std::get<protocol::Picture>(roundTrip(picture));
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        CHECK(back.rgb == picture.rgb);
        MESSAGE("600 x 400: " << line.size() << " bytes on the channel, serialized and parsed in " << ms << " ms");
        CHECK(ms < 1000.);
        for (std::size_t n : {0u, 1u, 2u, 3u, 4u, 5u}) {
            std::vector<std::uint8_t> bytes(n, 0xAB);
            CHECK(protocol::base64Decode(protocol::base64Encode(bytes)) == bytes);
        }
    }

    TEST_CASE("malformed messages are refused with the reason") {
        CHECK(refusal("passed").find("not a JSON object") != std::string::npos);
        CHECK(refusal(R"({"kind":"check","passed":true})").find("\"type\"") != std::string::npos);
        CHECK(refusal(R"({"type":"values","item":1,"outputs":[["x"]]})").find("not a number") != std::string::npos);
        CHECK(refusal(R"({"type":"picture","item":1,"width":2,"height":2,"rgb":"AAAA"})").find("bytes") !=
              std::string::npos);
        CHECK(refusal(R"({"type":"picture","item":1,"width":-2,"height":2,"rgb":""})").find("image of") !=
              std::string::npos);
        CHECK(refusal(R"({"type":"verdict","item":1})").find("unknown answer type") != std::string::npos);
        CHECK_FALSE(protocol::parseRequest(R"({"type":"check","item":1,"calls":[{"probe":"intersect","inputs":[1]}]})")
                        .message);
    }

    TEST_CASE("drawn cases change from one grading to the next, fixed cases stay") {
        const raylab::grader::LabCatalog labs =
            raylab::grader::loadLabCatalog(std::filesystem::path(RAYLAB_SOURCE_DIR) / "labs");
        const std::vector<raylab::grader::FunctionCheck> a = raylab::grader::functionChecks(labs, 1),
                                                         b = raylab::grader::functionChecks(labs, 2);
        REQUIRE(a.size() == b.size());
        int differing = 0;
        for (std::size_t k = 0; k < a.size(); ++k) {
            CHECK(a[k].id == b[k].id);
            CHECK(a[k].calls.front().inputs == b[k].calls.front().inputs); // the first case is a fixed one
            bool same = a[k].calls.size() == b[k].calls.size();
            for (std::size_t c = 0; same && c < a[k].calls.size(); ++c)
                same = a[k].calls[c].inputs == b[k].calls[c].inputs;
            differing += !same;
        }
        CHECK(3 * differing >= 2 * int(a.size())); // all but the few checks that are hard cases only
    }

    TEST_CASE("forged results in the channel, before the hello and from inside a check, earn nothing") {
        const GradeResult r = gradeAgent(courseSetup(), "raylab-bad-forges_answers");
        expectLabPoints(r, 1, 0.);
        bool named = false;
        for (const CheckOutcome& c : r.checks) {
            CHECK_MESSAGE(!(c.lab == 1 && c.passed), c.name);
            named = named || c.message.find("protocol violation: ") != std::string::npos;
        }
        CHECK_MESSAGE(named, failures(r));
        CHECK_FALSE(findFigure(r, "lab1_gradient")->passed);
    }

    TEST_CASE("answers learnt by heart for the fixed cases fail the drawn ones") {
        const GradeResult r = gradeAgent(courseSetup(), "raylab-bad-hard_coded");
        for (const char* name : {"corners_and_middle", "every_pixel", "one_pixel_wide"}) {
            const CheckOutcome* c = findCheck(r, name);
            REQUIRE(c);
            CHECK_FALSE(c->passed);
            CHECK_MESSAGE(c->message.find("Hint:") != std::string::npos, c->message);
        }
        CHECK(findFigure(r, "lab1_gradient")->passed); // the figure's size was learnt too: only the checks can tell
        expectLabPoints(r, 2, r.labs[1].maxPoints);
    }

    TEST_CASE("a picture rewritten after the render (atexit) changes nothing") {
        const fs::path reference = referencePicture("lab1_gradient");
#ifdef _WIN32
        _putenv_s("RAYLAB_HOSTILE_PNG", reference.string().c_str());
#else
        setenv("RAYLAB_HOSTILE_PNG", reference.string().c_str(), 1);
#endif
        GradeSetup setup = courseSetup();
        const GradeResult r = gradeCode(setup, {{binDir() / "raylab-bad-rewrites_png", 0}}, false);
        const FigureOutcome* f = findFigure(r, "lab1_gradient");
        REQUIRE(f);
        CHECK_FALSE(f->passed);
        REQUIRE_FALSE(f->studentImage.empty());
        // What the report shows is what was graded, not the reference copied over it.
        CHECK(raylab::readImage(f->studentImage).rgb != raylab::readImage(reference).rgb);
        fs::remove_all(setup.scratch);
        expectLabPoints(r, 3, r.labs[2].maxPoints);
    }

} // TEST_SUITE
