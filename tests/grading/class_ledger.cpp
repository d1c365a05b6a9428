// raylab grade-class as a ledger: interrupted at random points it resumes to the CSV of a quiet run;
// killed with SIGKILL it leaves nothing that stops the next run, and nor does raylab grade; a second
// run on the same --out refuses (or waits); hostile folder names each get their own row.
// The students are graded by a prebuilt agent (--agent), so no test here runs CMake.
#include "support/files.h"
#include "grader/course/class_run.h"
#include "src/text.h"
#include "grading_support.h"
#include "support/read_csv.h"
#include "support/small_disk.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <thread>
#include <utility>
#include <vector>
#include <unistd.h>
#if defined(__unix__) || defined(__APPLE__)
#include "program_process.h"
#define RAYLAB_LEDGER_TESTS 1
#endif
#ifdef __linux__
#include <sstream>
#include <sys/prctl.h>
#endif
#ifdef RAYLAB_LEDGER_TESTS
#include <fcntl.h>
#include <sys/file.h>
#endif

using namespace raylab::test;

#ifdef RAYLAB_LEDGER_TESTS

namespace {

// How many times `part` stands in `text`.
int count(const std::string& text, const std::string& part) {
    int found = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++found;
    return found;
}

using raylab::test::readFile;

ProgramProcess startRaylab(const std::vector<std::string>& args, const fs::path& output,
                           const std::vector<std::string>& environment = {}) {
    return startProgram(binDir() / "raylab", args, output, 0, environment);
}

// grade-class of `classDir` into `out`, every student graded by the reference agent on lab 1 (fast);
// without bubblewrap where this system cannot run it (grade-class refuses otherwise, as tested below).
// grade-class of lab 1 alone, with the reference's agent; `--no-sandbox` where bubblewrap cannot run
// (a chroot, a container), unless `asGiven`.
std::vector<std::string> classArgs(const fs::path& classDir, const fs::path& out, bool asGiven = false) {
    std::vector<std::string> args{"grade-class", classDir.string(), "--out", out.string(), "--agent",
                                  (binDir() / "raylab-agent-reference").string(), "--lab", "1", "--threads", "2",
                                  "--timeout", "60"};
    if (!asGiven && !bubblewrapMissing().empty()) args.push_back("--no-sandbox");
    return args;
}

using raylab::test::freshFolder;

// A class of small submissions (the agent grades, so their content does not matter; they are not empty).
fs::path makeClass(const fs::path& root, const std::vector<std::string>& names) {
    for (const std::string& name : names) {
        fs::create_directories(root / "class" / name / "lab1_first_image");
        std::ofstream(root / "class" / name / "lab1_first_image" / "gradient.cpp") << "// " << name << "\n";
    }
    return root / "class";
}

// The results of a run, by the folder each student got (none when it was stopped before it made
// the folder).
std::map<std::string, std::string> results(const fs::path& out) {
    std::map<std::string, std::string> found;
    if (!fs::exists(out / "students")) return found;
    for (const auto& entry : fs::directory_iterator(out / "students"))
        if (fs::exists(entry.path() / "result.json")) found[entry.path().filename().string()] = readFile(entry.path() / "result.json");
    return found;
}

const std::vector<std::string> kSix{"ann", "bob", "chloé", "dan", "eve", "fay"};

} // namespace

TEST_SUITE("class ledger") {

TEST_CASE("grade-class interrupted 5 times at random points (SIGINT, SIGTERM) resumes to the CSV of an uninterrupted run") {
    const fs::path root = freshFolder("raylab-ledger-interrupted");
    const fs::path classDir = makeClass(root, kSix);

    const auto start = std::chrono::steady_clock::now();
    ProgramProcess quiet = startRaylab(classArgs(classDir, root / "quiet"), root / "quiet.txt");
    REQUIRE_MESSAGE(quiet.finish() == 0, quiet.text());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::string expected = readFile(root / "quiet" / "grades.csv");
    REQUIRE(readCsv(expected).size() == kSix.size() + 1);
    const auto expectedResults = results(root / "quiet");

    const unsigned seed = std::random_device{}();
    std::mt19937 random(seed);
    // Up to half a whole run: each stop lands on a student being graded (or on the start), and the
    // runs go on from where the last one stopped.
    std::uniform_real_distribution<double> when(0., seconds / 2.);
    int stoppedWhileGrading = 0;
    for (int stop = 0; stop < 5; ++stop) {
        CAPTURE(seed);
        CAPTURE(stop);
        ProgramProcess run = startRaylab(classArgs(classDir, root / "stopped"), root / "stopped.txt");
        std::this_thread::sleep_for(std::chrono::duration<double>(when(random)));
        // To raylab alone, as Ctrl-C (SIGINT) or a service manager (SIGTERM) would: the processes
        // grading the student are its to stop.
        const int signal = stop % 2 == 0 ? SIGINT : SIGTERM;
        kill(run.pid, signal);
        const int status = run.finish();
        const std::string output = run.text();
        CHECK_MESSAGE((status == 128 + signal || status == 0), output);
        // Killed before it started grading (nothing printed yet), stopped cleanly, saying so, or killed
        // in the instant between its end (its last line printed) and the process's exit.
        if (status != 0 && !output.empty())
            CHECK_MESSAGE((output.find(signal == SIGINT ? "stopped by SIGINT" : "stopped by SIGTERM") != std::string::npos ||
                           output.find("grades: ") != std::string::npos),
                          output);
        if (output.find("interrupted: not graded") != std::string::npos) ++stoppedWhileGrading;
        // Every result written so far is the one an uninterrupted run writes: none is partial.
        for (const auto& [student, result] : results(root / "stopped")) CHECK(result == expectedResults.at(student));
        // The CSV holds them all, once each; a run stopped before its first result may have written none.
        const auto rows = readCsv(readFile(root / "stopped" / "grades.csv"));
        if (rows.empty()) CHECK(results(root / "stopped").empty());
        else CHECK(rows.size() == results(root / "stopped").size() + 1);
    }
    MESSAGE(stoppedWhileGrading << " of 5 stops fell on a student being graded (seed " << seed << ")");
    ProgramProcess last = startRaylab(classArgs(classDir, root / "stopped"), root / "stopped.txt");
    REQUIRE_MESSAGE(last.finish() == 0, last.text());
    CHECK(readFile(root / "stopped" / "grades.csv") == expected);
}

TEST_CASE("a result says what made it: grade-class --lab 1, then every lab, then another timeout grades each student "
          "again; the same settings do not") {
    const fs::path root = freshFolder("raylab-ledger-settings");
    const std::vector<std::string> two{"ann", "bob"};
    const fs::path classDir = makeClass(root, two);
    const auto run = [&](std::vector<std::string> args, const std::string& name) {
        ProgramProcess process = startRaylab(args, root / (name + ".txt"));
        const int status = process.finish();
        CHECK_MESSAGE(status == 0, process.text());
        return process.text();
    };
    const auto withoutLabOption = [](std::vector<std::string> args) {
        const auto lab = std::find(args.begin(), args.end(), "--lab");
        args.erase(lab, lab + 2);
        return args;
    };
    const fs::path out = root / "out";
    run(classArgs(classDir, out), "lab1");
    const nlohmann::json result = nlohmann::json::parse(readFile(out / "students" / "ann" / "result.json"));
    std::map<std::string, std::string> madeBy;
    for (const auto& setting : result.at("made_by")) madeBy[setting.at("name")] = setting.at("value");
    CHECK(madeBy.at("labs") == "1");
    CHECK(madeBy.at("timeout") == "60");
    CHECK(madeBy.at("grader") == "raylab " RAYLAB_VERSION);
    CHECK(madeBy.at("sandbox") == (bubblewrapMissing().empty() ? "bubblewrap" : "process group"));
    CHECK(madeBy.at("agents") == (binDir() / "raylab-agent-reference").string());
    const auto labOneOnly = readCsv(readFile(out / "grades.csv"));
    REQUIRE(labOneOnly.size() == 3);
    const auto column = [](const std::vector<std::vector<std::string>>& rows, const std::string& name) {
        const auto at = std::find(rows[0].begin(), rows[0].end(), name);
        REQUIRE_MESSAGE(at != rows[0].end(), "grades.csv has no column " << name);
        return std::size_t(at - rows[0].begin());
    };
    CHECK(labOneOnly[1][column(labOneOnly, "lab2")] == "0"); // lab 1 alone was graded

    const std::string all = run(withoutLabOption(classArgs(classDir, out)), "all");
    for (const std::string& name : two)
        CHECK_MESSAGE(all.find(name + std::string(20 - name.size(), ' ') + " graded again: its result was made with other "
                                                                            "settings (labs 1, now all)") != std::string::npos,
                      all);
    const auto rows = readCsv(readFile(out / "grades.csv"));
    REQUIRE(rows.size() == 3);
    for (const auto& row : {rows[1], rows[2]}) {
        CAPTURE(row[0]);
        for (const int lab : everyLab()) CHECK(std::stod(row[column(rows, "lab" + std::to_string(lab))]) > 0.);
        CHECK(row[column(rows, "total")] == row[column(rows, "max")]);
    }

    const std::string same = run(withoutLabOption(classArgs(classDir, out)), "same");
    CHECK_MESSAGE(same.find("graded again") == std::string::npos, same);
    CHECK_MESSAGE(same.find("already graded") != std::string::npos, same);
    std::vector<std::string> longer = withoutLabOption(classArgs(classDir, out));
    *(std::find(longer.begin(), longer.end(), "--timeout") + 1) = "90";
    const std::string other = run(longer, "timeout");
    CHECK_MESSAGE(other.find("graded again: its result was made with other settings (timeout 60, now 90)") != std::string::npos, other);
    CHECK(readCsv(readFile(out / "grades.csv")) == rows); // the same grades, made again
}

TEST_CASE("a second grade-class on the same --out refuses, naming the lock and the first run's pid; --wait waits") {
    const fs::path root = freshFolder("raylab-ledger-twice");
    const fs::path classDir = makeClass(root, kSix);
    ProgramProcess first = startRaylab(classArgs(classDir, root / "out"), root / "first.txt");
    // The lock holds the first run's pid once it has taken it.
    const fs::path lock = root / "out" / "grade-class.lock";
    for (int k = 0; k < 500 && readFile(lock) != std::to_string(first.pid) + "\n"; ++k)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    REQUIRE(readFile(lock) == std::to_string(first.pid) + "\n");

    ProgramProcess second = startRaylab(classArgs(classDir, root / "out"), root / "second.txt");
    const int secondStatus = second.finish();
    const std::string refused = second.text();
    CHECK(secondStatus == 1);
    CHECK_MESSAGE(refused.find("another grade-class run (pid " + std::to_string(first.pid) + ")") != std::string::npos, refused);
    CHECK_MESSAGE(refused.find(lock.string()) != std::string::npos, refused);
    CHECK_MESSAGE(refused.find("--wait") != std::string::npos, refused);

    std::vector<std::string> waitArgs = classArgs(classDir, root / "out");
    waitArgs.push_back("--wait");
    ProgramProcess waiting = startRaylab(waitArgs, root / "waiting.txt");
    CHECK(first.finish() == 0);
    CHECK(waiting.finish() == 0);
    const std::string waited = waiting.text();
    CHECK_MESSAGE(waited.find("waiting: another grade-class run (pid " + std::to_string(first.pid) + ")") != std::string::npos,
                  waited);
    for (const std::string& name : kSix) CHECK_MESSAGE(waited.find(name) != std::string::npos, waited);
    CHECK(waited.find("already graded") != std::string::npos);
    CHECK(readCsv(readFile(root / "out" / "grades.csv")).size() == kSix.size() + 1);

    // The lock of a run that died (its pid still in the file) is simply taken.
    std::ofstream(lock) << "999999999\n";
    ProgramProcess after = startRaylab(classArgs(classDir, root / "out"), root / "after.txt");
    CHECK_MESSAGE(after.finish() == 0, after.text());
}

#ifdef __linux__
// The processes of ours that are alive (not zombies): a subreaper adopts every orphan of its tree.
std::vector<pid_t> liveChildren() {
    std::vector<pid_t> alive;
    for (const auto& entry : fs::directory_iterator("/proc")) {
        const std::string name = entry.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos) continue;
        const std::string stat = readFile(entry.path() / "stat"); // pid (comm) state ppid ...
        const std::size_t close = stat.rfind(')');
        if (close == std::string::npos) continue;
        std::istringstream fields(stat.substr(close + 1));
        char state = 0;
        pid_t parent = 0;
        fields >> state >> parent;
        if (parent != getpid()) continue;
        if (state == 'Z') waitpid(pid_t(std::stol(name)), nullptr, WNOHANG);
        else alive.push_back(pid_t(std::stol(name)));
    }
    return alive;
}

std::vector<fs::path> scratchFolders(const fs::path& temporary, const std::string& prefix = "raylab-class-") {
    std::vector<fs::path> found;
    for (const auto& entry : fs::directory_iterator(temporary))
        if (entry.path().filename().string().rfind(prefix, 0) == 0) found.push_back(entry.path());
    return found;
}

TEST_CASE("grade-class killed with SIGKILL while grading: no process of it is left, the next run resumes at once and "
          "removes its scratch folder") {
    const fs::path root = freshFolder("raylab-ledger-sigkill");
    const fs::path classDir = makeClass(root, kSix);
    const fs::path temporary = root / "tmp"; // the runs' scratch folders, and only theirs
    fs::create_directories(temporary);
    const std::vector<std::string> environment{"TMPDIR=" + temporary.string()};
    ProgramProcess quiet = startProgram(binDir() / "raylab", classArgs(classDir, root / "quiet"), root / "quiet.txt", 0, environment);
    REQUIRE_MESSAGE(quiet.finish() == 0, quiet.text());
    CHECK(scratchFolders(temporary).empty()); // a run that ends removes its own

    // Every process raylab leaves behind becomes ours, to be seen.
    REQUIRE(prctl(PR_SET_CHILD_SUBREAPER, 1) == 0);
    ProgramProcess killed = startProgram(binDir() / "raylab", classArgs(classDir, root / "out"), root / "killed.txt", 0, environment);
    // Killed while a student is being graded: their folder is made just before their process starts,
    // and their result written when it ends.
    std::string beingGraded;
    for (int k = 0; k < 6000 && beingGraded.empty(); ++k) {
        if (fs::exists(root / "out" / "students"))
            for (const auto& entry : fs::directory_iterator(root / "out" / "students"))
                if (!fs::exists(entry.path() / "result.json")) beingGraded = entry.path().filename().string();
        if (beingGraded.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    REQUIRE_MESSAGE(!beingGraded.empty(), killed.text());
    kill(killed.pid, SIGKILL);
    CHECK(killed.finish() == 128 + SIGKILL);
    CHECK(scratchFolders(temporary).size() == 1); // left: nobody could remove it
    // Whatever it had started died with it (the bound only ends a failing test), before that
    // student's grading could finish.
    std::vector<pid_t> left = liveChildren();
    for (int k = 0; k < 1000 && !left.empty(); ++k) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        left = liveChildren();
    }
    CHECK_MESSAGE(left.empty(), left.size() << " processes of the killed run are still alive");
    for (pid_t pid : left) kill(pid, SIGKILL);
    CHECK_FALSE(fs::exists(root / "out" / "students" / beingGraded / "result.json"));

    // The next run takes the lock at once and removes the dead run's scratch folder.
    ProgramProcess next = startProgram(binDir() / "raylab", classArgs(classDir, root / "out"), root / "next.txt", 0, environment);
    const int nextStatus = next.finish();
    const std::string output = next.text();
    CHECK_MESSAGE(nextStatus == 0, output);
    CHECK_MESSAGE(output.find("another grade-class run") == std::string::npos, output);
    CHECK_MESSAGE(output.find("the scratch folder of a grade-class run that was killed") != std::string::npos, output);
    CHECK(scratchFolders(temporary).empty());
    CHECK(readFile(root / "out" / "grades.csv") == readFile(root / "quiet" / "grades.csv"));
    prctl(PR_SET_CHILD_SUBREAPER, 0);
    liveChildren(); // reaps
}
#endif

TEST_CASE("raylab grade killed with SIGKILL leaves its scratch folder, which the next grade removes; a live run's "
          "stays, and grade --images removes a dead one too") {
    const fs::path root = freshFolder("raylab-ledger-grade-sigkill");
    const fs::path temporary = root / "tmp"; // the runs' scratch folders, and only theirs
    fs::create_directories(temporary);
    const std::vector<std::string> environment{"TMPDIR=" + temporary.string()};
    const std::string agent = (binDir() / "raylab-agent-reference").string();
    ProgramProcess killed = startProgram(binDir() / "raylab", {"grade", "--agent", agent, "--report", (root / "r1").string()},
                                         root / "killed.txt", 0, environment);
    // Killed once its scratch folder is made and marked (the bound only ends a failing test).
    std::vector<fs::path> made;
    for (int k = 0; k < 12000 && made.empty(); ++k) {
        for (const fs::path& folder : scratchFolders(temporary, "raylab-grade-"))
            if (fs::exists(folder / ".raylab-run")) made.push_back(folder);
        if (made.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    REQUIRE_MESSAGE(made.size() == 1, killed.text());
    kill(killed.pid, SIGKILL);
    CHECK(killed.finish() == 128 + SIGKILL);
    kill(-killed.pid, SIGKILL); // whatever of its group is left
    CHECK(fs::exists(made[0])); // nobody could remove it

    // A live run's folder: its mark locked by this process, as a running grade holds its own.
    const fs::path live = temporary / "raylab-grade-live";
    fs::create_directories(live);
    std::ofstream(live / ".raylab-run") << "";
    const int held = ::open((live / ".raylab-run").c_str(), O_RDONLY | O_CLOEXEC);
    REQUIRE(held >= 0);
    REQUIRE(::flock(held, LOCK_EX | LOCK_NB) == 0);

    ProgramProcess next = startProgram(binDir() / "raylab", {"grade", "--lab", "1", "--agent", agent, "--report", (root / "r2").string()},
                                       root / "next.txt", 0, environment);
    const int nextStatus = next.finish();
    const std::string output = next.text();
    CHECK_MESSAGE(nextStatus == 0, output);
    CHECK_MESSAGE(output.find("removed " + made[0].string() + ": the scratch folder of a grade run that was killed") !=
                      std::string::npos,
                  output);
    CHECK_FALSE(fs::exists(made[0]));
    CHECK(scratchFolders(temporary, "raylab-grade-") == std::vector<fs::path>{live}); // its own removed at its end too
    ::close(held);

    // grade --images: the same for its own kind of folder (a mark no process holds is a dead run's).
    fs::create_directories(temporary / "raylab-images-dead");
    std::ofstream(temporary / "raylab-images-dead" / ".raylab-run") << "";
    fs::create_directories(root / "no-images");
    ProgramProcess images = startProgram(binDir() / "raylab", {"grade", "--images", (root / "no-images").string(), "--report",
                                                              (root / "r3").string()},
                                         root / "images.txt", 0, environment);
    images.finish(); // no image found: it fails, and still sweeps
    CHECK_MESSAGE(images.text().find("the scratch folder of a grade --images run that was killed") != std::string::npos,
                  images.text());
    CHECK(scratchFolders(temporary, "raylab-images-").empty());
}

// The first control character of `text` (C0 but for the line breaks `allowed`, DEL, C1 in UTF-8), shown
// with what precedes it; empty when there is none.
std::string controlCharacter(const std::string& text, const std::string& allowed = "\n") {
    for (std::size_t k = 0; k < text.size(); ++k) {
        const auto byte = static_cast<unsigned char>(text[k]);
        const bool c1 = byte == 0xC2 && k + 1 < text.size() && static_cast<unsigned char>(text[k + 1]) <= 0x9F;
        if (((byte < 0x20 || byte == 0x7F) && allowed.find(text[k]) == std::string::npos) || c1)
            return raylab::printableName(text.substr(k < 40 ? 0 : k - 40, 44));
    }
    return "";
}

TEST_CASE("hostile folder names each get their own row with their printable name and full points; formulas are "
          "defused; odd entries are skipped; no control character of a name reaches the console, the CSV or the "
          "reports; under each sandbox") {
    const std::vector<std::string> names{"x$(touch PWNED)", "back`touch PWNED`tick", "double\"quote", "it's", "with space",
                                         "-leading-dash", "ünïcödé 名前", "a,b", "new\nline", "grades.csv", "build",
                                         "students", "%41", "A", "=1+2*3", "=HYPERLINK(\"evil\",\"click\")", "bad\xFEname",
                                         "bad\xFFname", "esc\x1B[2J", "bell\a", "carriage\rreturn", "tab\there",
                                         "del\x7F", "c1 csi\xC2\x9B" "2J", "nul-free\x01\x02\x1F"};
    std::vector<std::string> sandboxes{""}; // the best this machine has (or none, where it has nothing)
    if (geteuid() == 0) sandboxes.push_back("fallback");
    for (const std::string& sandbox : sandboxes) {
        CAPTURE(sandbox);
        const fs::path root = freshFolder("raylab-ledger-names");
        const fs::path classDir = makeClass(root, names);
        std::ofstream(classDir / "notes.txt") << "not a submission";
        fs::create_directories(classDir / "empty");
        fs::create_directory_symlink(classDir / "A", classDir / "link");
        fs::create_directory_symlink("loop", classDir / "loop"); // a link to itself

        std::vector<std::string> args = classArgs(classDir, root / "out");
        if (!sandbox.empty()) std::erase(args, std::string("--no-sandbox"));
        std::vector<std::string> environment;
        if (!sandbox.empty()) environment.push_back("RAYLAB_SANDBOX=" + sandbox);
        ProgramProcess run = startRaylab(args, root / "output.txt", environment);
        const int status = run.finish();
        const std::string output = run.text();
        REQUIRE_MESSAGE(status == 0, output);
        CHECK_MESSAGE(controlCharacter(output).empty(), controlCharacter(output));
        const std::string csv = readFile(root / "out" / "grades.csv");
        CHECK_MESSAGE(controlCharacter(csv).empty(), controlCharacter(csv));
        for (const auto& entry : fs::recursive_directory_iterator(root / "out" / "students")) {
            if (entry.path().extension() != ".html" && entry.path().extension() != ".json") continue;
            CAPTURE(entry.path());
            const std::string text = readFile(entry.path());
            CHECK_MESSAGE(controlCharacter(text, "\n\t").empty(), controlCharacter(text, "\n\t"));
        }
        const std::string lines = "\n" + output;
        CHECK_MESSAGE(lines.find("\nskipped 'notes.txt': not a folder\n") != std::string::npos, output);
        CHECK_MESSAGE(lines.find("\nskipped 'empty': an empty folder\n") != std::string::npos, output);
        CHECK_MESSAGE(lines.find("\nskipped 'link': a symbolic link") != std::string::npos, output);
        CHECK_MESSAGE(lines.find("\nskipped 'loop': a symbolic link") != std::string::npos, output);
        CHECK_MESSAGE(output.find("new\\nline") != std::string::npos, output); // one line in the terminal
        CHECK_MESSAGE(output.find("bad\\xFEname") != std::string::npos, output);
        CHECK_MESSAGE(output.find("esc\\x1B[2J") != std::string::npos, output);
        CHECK_MESSAGE(output.find('\x1B') == std::string::npos, output);

        const auto rows = readCsv(csv);
        REQUIRE(!rows.empty());
        const std::vector<std::string>& header = rows[0];
        REQUIRE(header.size() >= 4);
        CHECK(header[0] == "student");
        const std::size_t total = std::size_t(std::find(header.begin(), header.end(), "total") - header.begin());
        REQUIRE(total + 1 < header.size());
        CHECK(rows.size() == names.size() + 1);
        // A spreadsheet reads a formula as text; two names that differ in bytes that are not UTF-8 differ.
        const auto shownInCsv = [](const std::string& name) {
            const std::string shown = raylab::printableName(name);
            return std::string("=+-@").find(shown[0]) != std::string::npos ? "'" + shown : shown;
        };
        CHECK(shownInCsv("=1+2*3") == "'=1+2*3");
        CHECK(shownInCsv("-leading-dash") == "'-leading-dash");
        CHECK(shownInCsv("bad\xFEname") == "bad\\xFEname");
        CHECK(shownInCsv("new\nline") == "new\\nline");
        for (const std::string& name : names) {
            CAPTURE(raylab::printableName(name));
            int found = 0;
            for (const auto& row : rows)
                if (row[0] == shownInCsv(name)) {
                    ++found;
                    REQUIRE(row.size() == header.size());
                    CHECK(row[total] == row[total + 1]); // total == max
                    CHECK(std::stod(row[total]) > 0.);
                }
            CHECK(found == 1);
        }
        CHECK(results(root / "out").size() == names.size()); // a folder each
        for (const fs::path& folder : {root, classDir, root / "out", fs::current_path()}) CHECK_FALSE(fs::exists(folder / "PWNED"));
    }
}

#ifdef __linux__
TEST_CASE("on Linux grade-class refuses to start without a working bubblewrap (or, as root, its fallback) unless "
          "--no-sandbox; raylab grade warns once") {
    const fs::path root = freshFolder("raylab-ledger-no-bubblewrap");
    const fs::path classDir = makeClass(root, {"ann"});
    // Two PATHs the grader looks bwrap up in: without it, and with one that cannot make its namespaces.
    const fs::path withoutBwrap = root / "path-without-bwrap", brokenBwrap = root / "path-with-broken-bwrap";
    fs::create_directories(withoutBwrap);
    fs::create_directories(brokenBwrap);
    fs::create_symlink("/bin/false", brokenBwrap / "bwrap");
    // As root the grader falls back on an unprivileged user: RAYLAB_SANDBOX=none takes that away, as on
    // a machine where the grader is not root (`fallback` true: left to it).
    const bool asRoot = geteuid() == 0;
    const auto runWith = [&](const fs::path& path, const std::vector<std::string>& args, bool fallback = false) {
        std::vector<std::string> environment{"PATH=" + path.string()};
        if (asRoot && !fallback) environment.push_back("RAYLAB_SANDBOX=none");
        const ProgramProcess process = startProgram(binDir() / "raylab", args, root / "output.txt", 0, environment);
        const int status = process.finish();
        return std::pair(status, process.text());
    };

    const auto [missingStatus, missing] = runWith(withoutBwrap, classArgs(classDir, root / "out", true));
    CHECK(missingStatus == 1);
    CHECK_MESSAGE(missing.find("grade-class needs bubblewrap on Linux") != std::string::npos, missing);
    CHECK_MESSAGE(missing.find("apt-get install -y bubblewrap") != std::string::npos, missing);
    CHECK_MESSAGE(missing.find("--no-sandbox") != std::string::npos, missing);
    CHECK_FALSE(fs::exists(root / "out")); // refused before it took the lock or graded anyone

    std::vector<std::string> french = classArgs(classDir, root / "out", true);
    french.insert(french.end(), {"--lang", "fr"});
    const auto [frenchStatus, frenchText] = runWith(withoutBwrap, french);
    CHECK(frenchStatus == 1);
    CHECK_MESSAGE(frenchText.find("grade-class a besoin de bubblewrap sous Linux") != std::string::npos, frenchText);
    CHECK_MESSAGE(frenchText.find("apt-get install -y bubblewrap") != std::string::npos, frenchText);
    CHECK_MESSAGE(frenchText.find("avec --no-sandbox") != std::string::npos, frenchText);

    const auto [brokenStatus, broken] = runWith(brokenBwrap, classArgs(classDir, root / "out", true));
    CHECK(brokenStatus == 1);
    CHECK_MESSAGE(broken.find((brokenBwrap / "bwrap").string() + " cannot create its namespaces here") != std::string::npos,
                  broken);
    CHECK_FALSE(fs::exists(root / "out"));

    std::vector<std::string> noSandbox = classArgs(classDir, root / "out");
    if (std::find(noSandbox.begin(), noSandbox.end(), "--no-sandbox") == noSandbox.end()) noSandbox.push_back("--no-sandbox");
    const auto [gradedStatus, graded] = runWith(withoutBwrap, noSandbox);
    CHECK_MESSAGE(gradedStatus == 0, graded);
    CHECK_MESSAGE(count(graded, "grading WITHOUT bubblewrap (turned off by --no-sandbox)") == 1, graded);
    const auto rows = readCsv(readFile(root / "out" / "grades.csv"));
    REQUIRE(rows.size() == 2);
    CHECK(rows[1][0] == "ann");

    // A student grading their own code needs no bubblewrap: one line says it is missing, and why (and,
    // as root, that the fallback runs the code as an unprivileged user).
    const auto [ownStatus, own] = runWith(withoutBwrap,
                                          {"grade", "--agent", (binDir() / "raylab-agent-reference").string(), "--lab", "1",
                                           "--threads", "2", "--report", (root / "report").string()},
                                          true);
    CHECK_MESSAGE(ownStatus == 0, own);
    // The command that installs it is this machine's: as root no sudo.
    const std::string why = "(bubblewrap is not installed (no bwrap in PATH; install it with " +
                            std::string(asRoot ? "apt-get install -y bubblewrap))" : "");
    CHECK_MESSAGE(count(own, asRoot ? "grading without bubblewrap " + why + ": the code graded runs as the unprivileged user"
                                    : "grading WITHOUT bubblewrap " + why) == 1,
                  own);

    if (!asRoot) return;
    // As root, grade-class accepts the fallback: the class is graded, each agent as an unprivileged user.
    const auto [fallbackStatus, fallback] = runWith(brokenBwrap, classArgs(classDir, root / "out-fallback", true), true);
    CHECK_MESSAGE(fallbackStatus == 0, fallback);
    CHECK_MESSAGE(count(fallback, "cannot create its namespaces here") == 1, fallback);
    CHECK_MESSAGE(count(fallback, "the code graded runs as the unprivileged user") == 1, fallback);
    const auto fallbackRows = readCsv(readFile(root / "out-fallback" / "grades.csv"));
    REQUIRE(fallbackRows.size() == 2);
    // Lab 1 earns every point: the agent reaches its scratch inside the run's (mkdtemp, root's 0700).
    const auto max = std::find(fallbackRows[0].begin(), fallbackRows[0].end(), "max");
    REQUIRE(max != fallbackRows[0].end());
    CHECK_MESSAGE(fallbackRows[1][1] == fallbackRows[1][std::size_t(max - fallbackRows[0].begin())], fallback);
}
#endif

#ifdef __linux__
// A real full disk: OUT is a tmpfs of 20 MB, filled but for about two students' results (48 KB each
// for lab 1). Under bubblewrap and under the fallback (as root), as every hostile case.
TEST_CASE("grade-class on a results disk that fills: said once, the student concerned not graded, every result kept; "
          "the same command resumes once there is room") {
    std::vector<std::string> sandboxes{"bubblewrap"};
    if (geteuid() == 0) sandboxes.push_back("fallback");
    for (const std::string& sandbox : sandboxes) {
        CAPTURE(sandbox);
        const fs::path root = freshFolder("raylab-ledger-full-disk-" + sandbox);
        const fs::path classDir = makeClass(root, kSix);
        SmallDisk disk(root / "out", 20);
        if (!disk.mounted()) {
            MESSAGE("SKIPPED: " << disk.why);
            return;
        }
        const fs::path filler = root / "out" / "filler";
        std::ofstream(filler, std::ios::binary) << std::string(fs::space(root / "out").available - (120 << 10), 'f');
        const auto run = [&](const std::string& name) {
            const std::vector<std::string> environment{"RAYLAB_SANDBOX=" + sandbox};
            ProgramProcess process = startProgram(binDir() / "raylab", classArgs(classDir, root / "out"), root / name, 0, environment);
            const int status = process.finish();
            return std::pair(status, process.text());
        };

        const auto [status, output] = run("full.txt");
        CHECK(status == 1);
        CHECK_MESSAGE(count(output, "not graded: disk full") == 1, output);
        CHECK_MESSAGE(count(output, "stopped: a disk is full") == 1, output);
        CHECK_MESSAGE(count(output, "No space left on device") == 1, output); // the file it could not write, once
        const std::size_t kept = results(root / "out").size();
        CHECK_MESSAGE((kept > 0 && kept < kSix.size()), output);
        CHECK(readCsv(readFile(root / "out" / "grades.csv")).size() == kept + 1);
        CHECK(output.find(kSix.back()) == std::string::npos); // stopped: the last student not tried

        fs::remove(filler); // room
        const auto [resumed, resumedOutput] = run("resumed.txt");
        CHECK_MESSAGE(resumed == 0, resumedOutput);
        CHECK(count(resumedOutput, "already graded") == int(kept));
        const auto rows = readCsv(readFile(root / "out" / "grades.csv"));
        REQUIRE(rows.size() == kSix.size() + 1);
        for (std::size_t k = 1; k < rows.size(); ++k) CHECK(rows[k][rows[k].size() - 3] == rows[k][rows[k].size() - 2]); // total == max
    }
}
#endif

} // TEST_SUITE

#endif
