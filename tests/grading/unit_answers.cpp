// The parent reads each run's answers: one per item, in order, after a hello; everything else is a
// protocol violation that fails an item with its reason, and a NaN is a value, not a violation.
#include "grader/judge/answers.h"
#include "src/messages.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace raylab::grader;
namespace protocol = raylab::grader::protocol;

namespace {

// Lab 3's probe computeNormal (7 inputs, 3 outputs), registered by its grading folder.
const protocol::ProbeSpec* computeNormal() {
    const protocol::ProbeSpec* probe = protocol::probeNamed("computeNormal");
    REQUIRE(probe != nullptr);
    return probe;
}

// Two checks of one call each, passing when the call returned 1, and a figure.
struct Session {
    std::vector<FunctionCheck> checks;
    FigureReference figure;
    std::vector<Item> items;
    std::map<std::uint64_t, Item*> byId;
    std::vector<Item*> sent;
    Reported reported;
    Ledger ledger{reported};

    Session() {
        for (const char* name : {"first", "second"})
            checks.push_back(
                {name,
                 {{computeNormal(), std::vector<double>(7)}},
                 [](const auto& out, Judge& judge) { judge.expectNear("value", out[0][0], 1., 0., "return 1"); },
                 1,
                 1.});
        figure.id = "fig";
        figure.lab = 1;
        items = {{1, &checks[0], nullptr, false}, {2, &checks[1], nullptr, false}, {3, nullptr, &figure, false}};
        for (Item& item : items) {
            byId[item.id] = &item;
            sent.push_back(&item);
        }
    }
    bool read(const std::vector<protocol::Answer>& answers, const std::vector<std::string>& extra = {},
              std::size_t at = 0) {
        std::vector<std::string> lines;
        for (const protocol::Answer& a : answers)
            lines.push_back(protocol::serialize(a));
        lines.insert(lines.begin() + std::ptrdiff_t(std::min(at, lines.size())), extra.begin(), extra.end());
        return readRun(lines, sent, byId, ledger);
    }
    const CheckOutcome& check(const std::string& name) { return reported.checks.at(name); }
};

const protocol::Answer kHello = protocol::Hello{protocol::kVersion};
protocol::Answer value(std::uint64_t item, double v) {
    return protocol::Values{item, {{v, 0., 0.}}};
}
protocol::Answer picture(std::uint64_t item) {
    return protocol::Picture{item, 1, 1, {1, 2, 3}};
}

bool violation(const CheckOutcome& c, const std::string& reason) {
    return !c.passed && c.message.find("protocol violation: " + reason) != std::string::npos;
}

} // namespace

TEST_SUITE("protocol session") {

    TEST_CASE("honest answers are judged by the parent") {
        Session s;
        CHECK(s.read({kHello, value(1, 1.), value(2, 0.5), picture(3), protocol::Done{}}));
        CHECK(s.check("first").passed);
        CHECK_FALSE(s.check("second").passed);
        CHECK(s.check("second").message.find("expected 1") != std::string::npos);
        CHECK(s.reported.figures.at("fig").image);
    }

    TEST_CASE("a NaN is a value the check judges, not a protocol violation") {
        Session s;
        s.read({kHello, value(1, std::nan("")), value(2, 1.), picture(3)});
        CHECK_FALSE(s.check("first").passed);
        CHECK(s.check("first").message.find("protocol violation") == std::string::npos);
        CHECK(s.check("second").passed);
    }

    TEST_CASE("a check whose message cannot be written costs that check alone, named as the course's fault") {
        Session s;
        s.checks[0].judge = [](const auto&, Judge&) { raylab::tr("grade.threw"); }; // {what} has no value
        CHECK(s.read({kHello, value(1, 1.), value(2, 1.), picture(3), protocol::Done{}}));
        CHECK_FALSE(s.check("first").passed);
        CHECK(s.check("first").message.find("could not judge this check (message grade.threw: no value for {what})") !=
              std::string::npos);
        CHECK(s.check("second").passed);
        CHECK(s.reported.figures.at("fig").image);
    }

    TEST_CASE("forged lines before the hello fail the awaited item only") {
        Session s;
        s.read({kHello, value(1, 1.), value(2, 1.), picture(3)}, {R"({"kind":"check","name":"first","passed":true})"});
        CHECK(violation(s.check("first"), "a malformed"));
        CHECK(s.check("second").passed);
    }

    TEST_CASE("an answer before the hello, out of order, for no item, or twice, is named") {
        {
            Session s;
            s.read({value(1, 1.), kHello, value(2, 1.), picture(3)});
            CHECK(violation(s.check("first"), "an answer before the hello"));
            CHECK(s.check("second").passed);
        }
        {
            Session s;
            s.read({kHello, value(2, 1.), value(1, 1.), value(2, 1.), picture(3)});
            CHECK(violation(s.check("second"), "an answer out of order"));
            CHECK(s.check("first").passed);
        }
        {
            Session s;
            s.read({kHello, value(99, 1.), value(1, 1.), value(2, 1.), picture(3)});
            CHECK(violation(s.check("first"), "an answer for item 99, which does not exist"));
            CHECK(s.check("second").passed);
        }
        {
            Session s; // a forged answer that passes, then the real one: the pass is undone
            s.read({kHello, value(1, 1.), value(1, 1.), value(2, 1.), picture(3)});
            CHECK(violation(s.check("first"), "a second answer"));
            CHECK(s.check("second").passed);
        }
    }

    TEST_CASE("an answer of the wrong type or size is a violation") {
        Session s;
        s.read({kHello, picture(1), protocol::Values{2, {{1., 0.}}}, value(3, 1.)});
        CHECK(violation(s.check("first"), "a function check was answered with something other than values"));
        CHECK(violation(s.check("second"), "the output of computeNormal is not of its probe's shape"));
        CHECK(s.reported.figures.at("fig").reason.find("protocol violation: a figure was answered") !=
              std::string::npos);
    }

    TEST_CASE("a second hello, a wrong version and an early done are named") {
        Session s;
        s.read({protocol::Hello{protocol::kVersion + 1}, value(1, 1.), kHello, value(2, 1.), protocol::Done{},
                picture(3)});
        CHECK(violation(s.check("first"), "protocol version"));
        CHECK(s.reported.figures.at("fig").reason.find("\"done\" before every item was answered") != std::string::npos);
    }

    TEST_CASE("a run that never said hello is told apart") {
        Session s;
        CHECK_FALSE(s.read({}));
        CHECK(s.reported.checks.empty());
    }

} // TEST_SUITE
