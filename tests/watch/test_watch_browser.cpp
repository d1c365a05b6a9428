// raylab watch as a student uses it, in the students' tree (raylab distribute) with labs 1 to 3
// written: the page in headless chromium shows lab 3's pictures passing; computeNormal is broken
// (the inward normal) and saved; the page refreshes by itself with the failing figure and check; a
// click on the sphere shows the student's normal beside the reference's, the first value that
// differs; a compile error keeps the last good pictures and verdicts, each marked stale, until it
// compiles again; an editor's temporary and swap files are never listed as saved. It prints the
// save-to-page time and the inspector's (a benchmark: no time is asserted), and takes the handouts'
// screenshot. Run under each sandbox (ctest's RAYLAB_SANDBOX).
#include "headless_chromium.h"

#include "support/files.h"
#include "support/needs.h"
#include "support/run_program.h"

#include "src/atomic_file.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <regex>

namespace fs = std::filesystem;
using namespace raylab::test;

namespace {

const fs::path kTree = RAYLAB_WATCH_TREE;
const fs::path kSphereFile = kTree / "labs" / "lab3_sphere" / "sphere_geometry.cpp";

// The solutions' files of labs 1 to 3, as a student who has written them has them.
void writeLabsOneToThree() {
    for (const auto& folder : fs::directory_iterator(fs::path(RAYLAB_SOURCE_DIR) / "solutions")) {
        const std::string name = folder.path().filename().string();
        if (name < "lab1" || name >= "lab4") continue;
        for (const auto& file : fs::directory_iterator(folder.path()))
            if (file.path().extension() == ".cpp") fs::copy_file(file.path(), kTree / "labs" / name / file.path().filename(),
                                                                 fs::copy_options::overwrite_existing);
    }
}

// `raylab watch 3` running in the tree until stopped with Ctrl-C (SIGINT), its output in a file; with
// `desktop`, it opens the browser (xdg-open, first found in that folder, on the display :0).
class Watch {
public:
    explicit Watch(const fs::path& output, const fs::path& desktop = {}) : m_output(output) {
        fs::remove(output);
        m_pid = fork();
        if (m_pid == 0) {
            const int fd = ::open(output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            dup2(fd, 1);
            dup2(fd, 2);
            if (chdir(kTree.c_str()) != 0) _exit(126);
            const std::string program = (kTree / "build" / "bin" / "raylab").string();
            if (desktop.empty()) {
                execl(program.c_str(), program.c_str(), "watch", "3", "--no-open", static_cast<char*>(nullptr));
            } else {
                const char* path = std::getenv("PATH");
                setenv("PATH", (desktop.string() + ":" + (path != nullptr ? path : "/usr/bin:/bin")).c_str(), 1);
                setenv("DISPLAY", ":0", 1);
                execl(program.c_str(), program.c_str(), "watch", "3", static_cast<char*>(nullptr));
            }
            _exit(127);
        }
    }
    ~Watch() {
        if (m_pid > 0) stop();
    }
    // The address it printed, once it has.
    std::string address() const {
        static const std::regex printed(R"((http://127\.0\.0\.1:\d+/[0-9a-f]{32}/))");
        for (int k = 0; k < 1200; ++k) {
            std::smatch m;
            const std::string text = readFile(m_output);
            if (std::regex_search(text, m, printed)) return m[1];
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
        return "";
    }
    // Ctrl-C: its exit status.
    int stop() {
        kill(m_pid, SIGINT);
        int status = 0;
        waitpid(m_pid, &status, 0);
        m_pid = -1;
        return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }

private:
    fs::path m_output;
    pid_t m_pid = -1;
};

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

TEST_SUITE("watch tree") {

TEST_CASE("the students' tree with labs 1 to 3 written, built") {
    const fs::path out = fs::path(RAYLAB_WATCH_TREE).parent_path();
    fs::remove_all(kTree);
    fs::create_directories(out);
    const ProgramRun distributed =
        runProgram({fs::path(RAYLAB_BIN_DIR) / "raylab", "distribute", kTree.string()}, out / "watch-distribute.txt");
    REQUIRE_MESSAGE(distributed.status == 0, distributed.output);
    writeLabsOneToThree();
    const ProgramRun configured = runProgram({RAYLAB_CMAKE_COMMAND, "-S", kTree.string(), "-B", (kTree / "build").string(), "-G",
                                              RAYLAB_CMAKE_GENERATOR, "-DBUILD_TESTING=OFF"},
                                             out / "watch-configure.txt");
    REQUIRE_MESSAGE(configured.status == 0, configured.output);
    const ProgramRun built = runProgram(
        {RAYLAB_CMAKE_COMMAND, "--build", (kTree / "build").string(), "-j", "2", "--target", "raylab", "raylab-agents"},
        out / "watch-build.txt");
    REQUIRE_MESSAGE(built.status == 0, built.output);
}

} // TEST_SUITE

TEST_SUITE("watch opens the browser") {

TEST_CASE("the browser is given a file its owner alone can read, never the page's token") {
    REQUIRE_MESSAGE(fs::exists(kTree / "build" / "bin" / "raylab"), "the tree is built by the test 'watch_browser_tests/watch tree'");
    const fs::path out = fs::path(RAYLAB_WATCH_TREE).parent_path();
    // A desktop whose xdg-open writes down what it was given, and a copy of the file it was given.
    const fs::path desktop = out / "watch-desktop";
    fs::remove_all(desktop);
    fs::create_directories(desktop);
    const fs::path given = desktop / "given.txt", copied = desktop / "copied.html";
    raylab::writeFileAtomically(desktop / "xdg-open", "#!/bin/sh\nprintf '%s\\n' \"$@\" > '" + given.string() + ".partial'\ncp \"$1\" '" +
                                                          copied.string() + "'\nmv '" + given.string() + ".partial' '" + given.string() + "'\n");
    fs::permissions(desktop / "xdg-open", fs::perms::owner_all);
    Watch watch(out / "watch-output-opened.txt", desktop);
    const std::string address = watch.address();
    REQUIRE_MESSAGE(!address.empty(), readFile(out / "watch-output-opened.txt"));
    for (int k = 0; k < 600 && !fs::exists(given); ++k) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    REQUIRE_MESSAGE(fs::exists(given), readFile(out / "watch-output-opened.txt"));
    const std::string arguments = readFile(given);
    const std::string token = address.substr(address.size() - 33, 32);
    CHECK_MESSAGE(arguments.find(token) == std::string::npos, arguments); // nothing a `ps` shows opens the page
    const fs::path launcher = arguments.substr(0, arguments.find('\n'));
    CHECK(readFile(copied).find("url=" + address + "\"") != std::string::npos); // the file leads to the page
    const fs::perms folder = fs::status(launcher.parent_path()).permissions();
    CHECK((folder & (fs::perms::group_all | fs::perms::others_all)) == fs::perms::none); // no other user enters
    CHECK(watch.stop() == 0);
}

} // TEST_SUITE

TEST_SUITE("watch in a browser") {

TEST_CASE("a broken computeNormal: the page refreshes by itself, the inspector shows the normal that differs") {
    const fs::path chromium = neededProgram("chromium", "chromium");
    if (chromium.empty()) return;
    REQUIRE_MESSAGE(fs::exists(kTree / "build" / "bin" / "raylab"), "the tree is built by the test 'watch_browser_tests/watch tree'");
    writeLabsOneToThree(); // as written, whatever a previous run left
    const std::string sandbox = std::getenv("RAYLAB_SANDBOX") ? std::getenv("RAYLAB_SANDBOX") : "bubblewrap";
    const fs::path out = fs::path(RAYLAB_WATCH_TREE).parent_path();

    Watch watch(out / ("watch-output-" + sandbox + ".txt"));
    const std::string address = watch.address();
    REQUIRE_MESSAGE(!address.empty(), readFile(out / ("watch-output-" + sandbox + ".txt")));
    HeadlessChromium browser(chromium, out / ("watch-chromium-" + sandbox), 1600, 1000);
    browser.open(address);

    // Lab 3 as written: its three figures pass.
    const std::string cosine = "document.querySelector('#figure-lab3_cosine h2 b')";
    REQUIRE(browser.waitFor("document.body.dataset.phase === 'ready' && " + cosine));
    CHECK(browser.evaluate(cosine + ".className") == "pass");
    CHECK(browser.evaluate("document.querySelectorAll('#checks tr.failed').length") == 0);
    const int before = std::stoi(browser.evaluate("document.body.dataset.version").get<std::string>());

    // The inward normal, saved as an editor saves.
    std::string code = readFile(kSphereFile);
    const std::string outward = "(p - m_center)";
    REQUIRE(code.find(outward) != std::string::npos);
    code.replace(code.find(outward), outward.size(), "(m_center - p)");
    // Saved as sed -i saves (a temporary file beside it, renamed over it), a vim swap file beside it.
    const auto saved = std::chrono::steady_clock::now();
    raylab::writeFileAtomically(kSphereFile.parent_path() / ".sphere_geometry.cpp.swp", "swap");
    raylab::writeFileAtomically(kSphereFile.parent_path() / "sedvVUgJG", code);
    fs::rename(kSphereFile.parent_path() / "sedvVUgJG", kSphereFile);
    REQUIRE(browser.waitFor("Number(document.body.dataset.version) > " + std::to_string(before) +
                            " && document.body.dataset.phase === 'ready'"));
    const double saveToPage = secondsSince(saved);
    CHECK(browser.evaluate(cosine + ".className") == "fail");
    CHECK(browser.evaluate("[...document.querySelectorAll('#checks tr.failed')].some(r => r.textContent.includes('computeNormal'))") ==
          true);
    CHECK(browser.evaluate("document.getElementById('changed').textContent.includes('sphere_geometry.cpp')") == true);
    CHECK(browser.evaluate("document.getElementById('changed').textContent.includes('sed')") == false); // the editors' files are no lab file
    CHECK(browser.evaluate("document.getElementById('changed').textContent.includes('swp')") == false);
    CHECK(browser.evaluate("document.body.dataset.stale") == "no");
    CHECK(browser.evaluate("document.querySelectorAll('.stale-label').length") == 0);
    fs::remove(kSphereFile.parent_path() / ".sphere_geometry.cpp.swp");

    // Zoomed in (+ twice: each pixel of the picture two pixels of the screen), a click on the
    // sphere's upper half in the student's picture (pixel 300, 150 of 600 x 400).
    const std::string picture = "document.querySelector('#figure-lab3_cosine img[data-kind=yours]')";
    REQUIRE(browser.waitFor(picture + ".complete && " + picture + ".naturalWidth === 600"));
    browser.press("+");
    browser.press("+");
    CHECK(browser.evaluate(picture + ".clientWidth") == 1200);
    browser.evaluate(picture + ".scrollIntoView({block: 'center', inline: 'center'})"); // the sphere in sight
    const nlohmann::json box = browser.evaluate("(() => { const p = " + picture + ", r = p.getBoundingClientRect(); " +
                                                "return [r.left + p.clientLeft, r.top + p.clientTop, p.clientWidth, p.clientHeight]; })()");
    const auto asked = std::chrono::steady_clock::now();
    browser.click(box[0].get<double>() + 300.5 / 600. * box[2].get<double>(), box[1].get<double>() + 150.5 / 400. * box[3].get<double>());
    REQUIRE(browser.waitFor("document.getElementById('inspector').dataset.state === 'answered'"));
    const double inspectorSeconds = secondsSince(asked);
    CHECK(browser.evaluate("document.getElementById('inspector-where').textContent") == "figure lab3_cosine, pixel (300, 150)");
    const nlohmann::json rows = browser.evaluate(
        "[...document.querySelectorAll('#inspector-rows tr[data-name]')].map(r => ({name: r.dataset.name, "
        "first: r.classList.contains('first'), differs: r.classList.contains('differs'), "
        "student: r.querySelector('.student').textContent, reference: r.querySelector('.reference').textContent, "
        "formula: r.querySelector('.formula').textContent, handout: r.querySelector('.handout').textContent}))");
    INFO(rows.dump(1));
    REQUIRE(rows.size() == 8); // (sx, sy), origin, direction, hit, t, position, normal, colour
    std::size_t first = rows.size();
    for (std::size_t k = 0; k < rows.size(); ++k)
        if (rows[k]["first"] == true) first = k;
    REQUIRE(first < rows.size());
    CHECK(rows[first]["name"] == "normal");
    CHECK(rows[first]["formula"] == "n = (p - c) / r");
    CHECK(rows[first]["handout"] == "handout: labs/lab3_sphere/README.md#the-normal");
    CHECK(rows[first]["student"] != rows[first]["reference"]);
    for (std::size_t k = 0; k < first; ++k) CHECK_MESSAGE(rows[k]["differs"] == false, rows[k]["name"]);
    CHECK(rows[7]["name"] == "colour");
    CHECK(rows[7]["differs"] == true); // black: the cosine of the inward normal is negative

    // F flips the student's picture to the reference.
    browser.press("f");
    CHECK(browser.evaluate(picture + ".getAttribute('src').includes('reference')") == true);
    if (sandbox == "bubblewrap") { // the handouts' screenshot: the page as the click left it, from its top
        browser.press("f");
        browser.press("-");
        browser.press("-");
        browser.evaluate("window.scrollTo(0, 0)");
        raylab::writeFileAtomically(RAYLAB_WATCH_SCREENSHOT, [&] {
            const std::vector<std::uint8_t> png = browser.screenshot();
            return std::string(png.begin(), png.end());
        }());
    }
    std::printf("raylab watch (%s): save to refreshed page %.2f s, inspector's answer %.0f ms\n", sandbox.c_str(), saveToPage,
                inspectorSeconds * 1000.);
    std::fflush(stdout);

    // A compile error: the page names its file and line.
    const std::string inward = code;
    const std::size_t line = std::size_t(std::count(code.begin(), code.begin() + std::ptrdiff_t(code.find("(m_center - p)")), '\n')) + 1;
    code.replace(code.find("(m_center - p)"), 14, "(m_center - nowhere)");
    const auto version = [&] { return browser.evaluate("document.body.dataset.version").get<std::string>(); };
    std::string seen = version();
    raylab::writeFileAtomically(kSphereFile, code);
    REQUIRE(browser.waitFor("document.body.dataset.version !== '" + seen + "' && document.body.dataset.phase === 'build_failed'"));
    const std::string where = "labs/lab3_sphere/sphere_geometry.cpp:" + std::to_string(line) + ":";
    const std::string shown = browser.evaluate("document.querySelector('#build-errors code.where').textContent").get<std::string>();
    CHECK_MESSAGE(shown.rfind(where, 0) == 0, shown);
    CHECK(browser.evaluate("document.getElementById('build-errors').textContent.includes('nowhere')") == true);
    // The last good build's pictures and verdicts are still there, each marked stale, with a banner.
    CHECK(browser.evaluate("document.body.dataset.stale") == "yes");
    CHECK(browser.evaluate("document.getElementById('stale').hidden") == false);
    CHECK(browser.evaluate("document.getElementById('stale').textContent.length > 20") == true); // in the reader's language
    CHECK(browser.evaluate("(() => { const f = document.querySelectorAll('.figure'); return f.length > 0 && "
                           "[...f].every(b => b.classList.contains('stale') && b.querySelector('h2 .stale-label')); })()") == true);
    CHECK(browser.evaluate("(() => { const c = document.querySelectorAll('#checks tr'); return c.length > 0 && "
                           "[...c].every(r => r.querySelector('.stale-label') && r.querySelector('.stale-label').textContent !== ''); })()") == true);

    // A save during a build is not lost: the inward normal saved, then, while it builds, the outward
    // one; the page ends with the outward normal's grade.
    seen = version();
    raylab::writeFileAtomically(kSphereFile, inward);
    REQUIRE(browser.waitFor("document.body.dataset.version !== '" + seen + "' && document.body.dataset.phase === 'building'"));
    writeLabsOneToThree();
    CHECK(browser.waitFor("document.body.dataset.phase === 'ready' && " + cosine + ".className === 'pass'"));
    CHECK(browser.evaluate("document.querySelectorAll('#checks tr.failed').length") == 0);
    CHECK(browser.evaluate("document.body.dataset.stale") == "no"); // it compiles again: nothing stale
    CHECK(browser.evaluate("document.getElementById('stale').hidden") == true);
    CHECK(browser.evaluate("document.querySelectorAll('.stale-label, .figure.stale').length") == 0);

    CHECK(watch.stop() == 0); // Ctrl-C stops it cleanly
    CHECK(readFile(out / ("watch-output-" + sandbox + ".txt")).find("raylab watch: stopped") != std::string::npos);
}

} // TEST_SUITE
