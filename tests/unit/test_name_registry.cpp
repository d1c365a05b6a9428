// The one registry of names (src/name_registry.h) behind the integrators, probes, checks and figure
// steps: a name registered twice is an error naming both lines, the names come sorted, an unknown
// name is not found; and the integrators' registry, the one a lab uses, refuses a taken name.
#include "src/name_registry.h"
#include "raylab/integrator_registry.h"

#include <doctest/doctest.h>

#include <stdexcept>
#include <string>
#include <vector>

using raylab::NameRegistry;
using raylab::SourcePlace;

TEST_SUITE("name registry") {
    TEST_CASE("a name registered twice is an error naming both places") {
        NameRegistry<int> registry("number");
        registry.add("seven", 7, SourcePlace{"framework/grader/labs/lab7_x/steps.cpp", 12});
        CHECK_THROWS_WITH_AS(registry.add("seven", 8, SourcePlace{"/home/me/raylab/framework/grader/labs/lab8_y/steps.cpp", 30}),
                             "framework/grader/labs/lab8_y/steps.cpp:30: the name 'seven' (number) is registered twice, "
                             "first at framework/grader/labs/lab7_x/steps.cpp:12",
                             std::logic_error);
        REQUIRE(registry.find("seven") != nullptr);
        CHECK(registry.find("seven")->value == 7); // the first one stays
    }

    TEST_CASE("the place is the line that registers, by default") {
        const SourcePlace here = SourcePlace::here();
        CHECK(std::string(here.file).find("test_name_registry.cpp") != std::string::npos);
        CHECK(here.line == __LINE__ - 2);
    }

    TEST_CASE("the names come sorted, whatever the order they were registered in") {
        NameRegistry<int> registry("number");
        for (const char* name : {"lab3", "Lab10", "lab1", "lab10", "lab2"})
            registry.add(name, 0, SourcePlace::here());
        CHECK(registry.names() == std::vector<std::string>{"Lab10", "lab1", "lab10", "lab2", "lab3"});
    }

    TEST_CASE("an unknown name is not found, and an entry found stays where it is") {
        NameRegistry<std::string> registry("word");
        CHECK(registry.find("anything") == nullptr);
        const auto& first = registry.add("a", "alpha", SourcePlace::here());
        for (int k = 0; k < 100; ++k)
            registry.add(std::to_string(k), "beta", SourcePlace::here());
        CHECK(registry.find("A") == nullptr);
        REQUIRE(registry.find("a") == &first);
        CHECK(first.value == "alpha");
        CHECK(registry.names().size() == 101);
    }

    TEST_CASE("an integrator's name that lab 3 registered is refused, naming lab 3's line") {
        const auto flat = [] { return std::unique_ptr<raylab::Integrator>(); };
        const std::string here = "tests/unit/test_name_registry.cpp:" + std::to_string(__LINE__ + 1) + ": ";
        CHECK_THROWS_WITH_AS(raylab::registerIntegrator("flat", flat), doctest::Contains(here.c_str()), std::logic_error);
        CHECK_THROWS_WITH_AS(raylab::registerIntegrator("flat", flat),
                             doctest::Contains("the name 'flat' (integrator) is registered twice, first at "
                                               "framework/grader/labs/lab3_sphere/shadings.cpp:"),
                             std::logic_error);
        CHECK(raylab::isRegisteredIntegrator("flat"));
        CHECK_FALSE(raylab::isRegisteredIntegrator("gradient")); // an image, not an integrator
        CHECK(raylab::isRegisteredImage("gradient"));
    }
}
