// The watch page itself (templates/, embedded in raylab) in headless chromium, against its real
// server, with documents made as raylab watch makes them (page_document.h) and a canned inspector:
// under a compile error every figure and check is marked stale, with a banner and the compiler's
// error; once it compiles, nothing is; the inspector's rows that follow the reference's ray are
// preceded by a line saying so, and a row of the reference's path never shows a value as yours. Fast
// (no tree, no build): the browser test of the students' tree checks the same in a real session. And
// the page's "word: value" in French typography.
#include "headless_chromium.h"

#include "support/files.h"
#include "support/needs.h"

#include "src/messages.h"
#include "watch/page_document.h"
#include "watch/watch_server.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <thread>

namespace fs = std::filesystem;
using nlohmann::json;
using namespace raylab::watch;

namespace {

const std::string kGraded = R"({"figures":[{"id":"lab3_cosine","passed":true,"reason":"","diagnosis":"","width":4,"height":4,
"student":"","reference":"","difference":"","scale":"LSB"},{"id":"lab3_flat","passed":false,"reason":"","diagnosis":"","width":4,
"height":4,"student":"","reference":"","difference":"","scale":"LSB"}],
"checks":[{"name":"intersect: a ray along z","passed":true,"message":"","points":1,"max":1}],"labs":[],
"problems":["lab3_flat: rendering crashed"]})";

// An inspector's answer: a camera row that differs, a row on the reference's ray, a row of the
// reference's path alone.
std::string cannedInspection(const std::string& figure, int x, int y) {
    json rows = json::array();
    const auto row = [&](const std::string& name, json student, json reference, bool differs, const std::string& follows, bool only) {
        rows.push_back({{"name", name}, {"function", only ? "" : "f"}, {"reference", reference}, {"student", student},
                        {"differs", differs}, {"reference_only", only}, {"follows", follows}, {"formula", "x"}, {"handout", "h"}});
    };
    const std::string follows = raylab::tr("watch.follows.ray");
    row("camera u", json::array({1., 0., 0.}), json::array({-1., 0., 0.}), true, "", false);
    row("hit", true, true, false, follows, false);
    row("colour", json::array({0.5, 0.5, 0.5}), json::array({0.5, 0.5, 0.5}), false, follows, false);
    row("light 1: shadow ray origin", nullptr, json::array({0., 0., 1.}), false, "", true);
    return json{{"figure", figure}, {"x", x}, {"y", y}, {"rows", rows}, {"first", 0}, {"note", ""}}.dump();
}

} // namespace

TEST_SUITE("watch page") {

TEST_CASE("stale marks under a compile error, cleared when it compiles; the inspector's rows on the reference's ray say so") {
    const fs::path chromium = raylab::test::neededProgram("chromium", "chromium");
    if (chromium.empty()) return;
    raylab::setLanguage(raylab::Language::En); // the page's words, whatever the locale
    const fs::path root = raylab::test::freshFolder("watch-page");
    PageState page;
    WatchServer server(page, root, "0123456789abcdef0123456789abcdef", cannedInspection);
    const int port = server.bind(0);
    std::thread serving([&server] { server.serve(); });
    struct Stop { // also when a REQUIRE leaves early
        WatchServer& server;
        std::thread& serving;
        ~Stop() {
            server.stop();
            serving.join();
        }
    } stop{server, serving};
    const std::string error = "/tree/labs/lab3_sphere/sphere_geometry.cpp:12:5: error: 'nowhere' was not declared in this scope\n";
    page.publish(pageDocument(kGraded, {3, "build_failed", {"labs/lab3_sphere/sphere_geometry.cpp"}, error, "/tree"}));
    {
        raylab::test::HeadlessChromium browser(chromium, root.parent_path() / "watch-page-chromium", 1200, 800);
        browser.open("http://127.0.0.1:" + std::to_string(port) + "/0123456789abcdef0123456789abcdef/");
        REQUIRE(browser.waitFor("document.body.dataset.phase === 'build_failed'", 60.));
        CHECK(browser.evaluate("document.body.dataset.stale") == "yes");
        CHECK(browser.evaluate("document.getElementById('stale').hidden") == false);
        CHECK(browser.evaluate("document.getElementById('stale').textContent.includes('does not compile')") == true);
        CHECK(browser.evaluate("document.getElementById('build').hidden") == false);
        CHECK(browser.evaluate("document.querySelector('#build-errors code.where').textContent") == "labs/lab3_sphere/sphere_geometry.cpp:12:5");
        CHECK(browser.evaluate("document.querySelectorAll('.figure.stale h2 .stale-label').length") == 2);
        CHECK(browser.evaluate("document.querySelector('#figure-lab3_cosine h2 b').className") == "pass"); // the verdict kept, marked
        CHECK(browser.evaluate("document.querySelectorAll('#checks tr.stale .stale-label').length") == 1);
        CHECK(browser.evaluate("document.querySelector('#checks .stale-label').textContent") == "stale");
        CHECK(browser.evaluate("document.querySelectorAll('#problems h2 .stale-label').length") == 1);

        // It compiles again: nothing is stale, the errors are gone.
        page.publish(pageDocument(kGraded, {3, "ready", {"labs/lab3_sphere/sphere_geometry.cpp"}, "", "/tree"}));
        REQUIRE(browser.waitFor("document.body.dataset.phase === 'ready'", 60.));
        CHECK(browser.evaluate("document.body.dataset.stale") == "no");
        CHECK(browser.evaluate("document.getElementById('stale').hidden") == true);
        CHECK(browser.evaluate("document.getElementById('build').hidden") == true);
        CHECK(browser.evaluate("document.querySelectorAll('.stale-label, .figure.stale, #checks tr.stale').length") == 0);

        // The inspector: one line before the rows on the reference's ray, none before the others.
        browser.evaluate("inspect('lab4_d', 1, 2)");
        REQUIRE(browser.waitFor("document.getElementById('inspector').dataset.state === 'answered'", 60.));
        const json lines = browser.evaluate("[...document.querySelectorAll('#inspector-rows tr.follows')].map(r => r.textContent)");
        REQUIRE(lines.size() == 1);
        CHECK(lines[0].get<std::string>().starts_with("from here on: the reference's ray, not yours"));
        CHECK(browser.evaluate("(() => { const l = document.querySelector('#inspector-rows tr.follows'); "
                               "return l.previousElementSibling.dataset.name + '|' + l.nextElementSibling.dataset.name; })()") ==
              "camera u|hit");
        CHECK(browser.evaluate("document.querySelectorAll('#inspector-rows tr.following').length") == 2);
        const std::string only = "document.querySelector('#inspector-rows tr.reference-only .student').textContent";
        CHECK(browser.evaluate(only) == raylab::tr("watch.page.reference_only"));

        // "word: value" in each language's typography: a no-break space before the colon in French.
        CHECK(browser.evaluate("document.getElementById('changed').textContent") == "saved: labs/lab3_sphere/sphere_geometry.cpp");
        raylab::setLanguage(raylab::Language::Fr);
        page.publish(pageDocument(kGraded, {3, "ready", {"labs/lab3_sphere/sphere_geometry.cpp"}, "", "/tree"}));
        raylab::setLanguage(raylab::Language::En);
        REQUIRE(browser.waitFor("document.documentElement.lang === 'fr'", 60.));
        CHECK(browser.evaluate("document.getElementById('changed').textContent") ==
              "enregistr\u00E9\u00A0: labs/lab3_sphere/sphere_geometry.cpp");
        CHECK(browser.evaluate("document.querySelector('.difference-caption').textContent") == "diff\u00E9rence\u00A0: LSB");
    }
}

} // TEST_SUITE
