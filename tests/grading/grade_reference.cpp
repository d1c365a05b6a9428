// The reference solutions pass, with any thread count and seed; the references are what the
// solutions make; the stubs get zero and are told which function to write.
#include "grading_support.h"

#include "grader/channel.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <set>

using namespace raylab::test;

TEST_SUITE("grade reference") {

TEST_CASE("the reference solutions get every point, on 1 or 2 threads and several seeds") {
    for (const auto& [threads, seed] : {std::pair{1, -1LL}, std::pair{2, 12345LL}, std::pair{2, 777LL}}) {
        GradeSetup setup = courseSetup();
        setup.threads = threads;
        setup.seed = seed;
        const GradeResult r = gradeAgent(setup, "raylab-agent-reference");
        CHECK_MESSAGE(r.allPassed(), "threads " << threads << ", seed " << seed << failures(r));
        CHECK(r.score() == r.maxScore());
        std::size_t tableChecks = 0;
        for (const auto& [lab, items] : setup.points.labs)
            for (const auto& [item, points] : items) tableChecks += item.rfind("figure ", 0) != 0;
        CHECK(r.checks.size() == tableChecks);
        CHECK(r.figures.size() == setup.references.figures.size());
    }
}

TEST_CASE("every check the agent runs is in the points table, and the other way round") {
    const fs::path list = fs::temp_directory_path() / "raylab-agent-list.jsonl";
    fs::remove(list);
    const std::string command = (binDir() / "raylab-agent-reference").string() + " --list --report-file " + list.string();
    REQUIRE(std::system(command.c_str()) == 0);
    std::set<std::string> listed;
    std::ifstream in(list);
    for (std::string line; std::getline(in, line);) {
        const nlohmann::json j = nlohmann::json::parse(line);
        if (j["kind"] != "listed") continue;
        const std::string suite = j["suite"], name = j["name"];
        listed.insert(name);
        CHECK_MESSAGE(courseSetup().points.has(suite[3] - '0', name), suite << ": \"" << name << "\" has no points");
        CHECK_MESSAGE(name.find_first_of(",*?") == std::string::npos, name << ": doctest filters split on , * ?");
    }
    for (const auto& [lab, items] : courseSetup().points.labs)
        for (const auto& [item, points] : items)
            if (item.rfind("figure ", 0) != 0) CHECK_MESSAGE(listed.count(item), "the points table names \"" << item << "\", which no check has");
}

TEST_CASE("the stubs of labs/ get zero, each check saying what to write") {
    GradeSetup setup = courseSetup();
    bool isolated = false;
    std::vector<AgentPlan> agents;
    for (int lab = 1; lab <= 5; ++lab) agents.push_back({binDir() / ("raylab-agent-lab" + std::to_string(lab)), lab});
    const GradeResult r = gradeCode(setup, agents, true);
    fs::remove_all(setup.scratch);
    (void)isolated;
    CHECK(r.score() == 0.);
    const CheckOutcome* c = findCheck(r, "generateRay: directions are unit vectors");
    REQUIRE(c);
    CHECK(c->message.find("lab 2 not done yet: write PerspectiveCamera::updateViewport") != std::string::npos);
    const FigureOutcome* f = findFigure(r, "lab3_cosine");
    REQUIRE(f);
    CHECK(f->reason.find("lab 3 not done yet") != std::string::npos);
    CHECK(r.labs[2].notes.front().find("other labs came from the reference") != std::string::npos);
}

} // TEST_SUITE
