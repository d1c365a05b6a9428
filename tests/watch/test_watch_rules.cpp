// raylab watch's parts that decide alone: what the server serves (the token, the Host header, the
// files of its folder), the compiler's errors it shows, the long poll's versions and the file watcher.
#include "watch/bounded_server.h"
#include "watch/compiler_errors.h"
#include "watch/file_watcher.h"
#include "watch/http_rules.h"
#include "watch/page_document.h"
#include "watch/page_state.h"
#include "watch/watch_server.h"
#include "watch/watch_session.h"

#include "src/atomic_file.h"
#include "src/messages.h"
#include "support/files.h"

#include <doctest/doctest.h>
#include <httplib.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

#ifndef _WIN32
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>
#endif

namespace fs = std::filesystem;
using namespace raylab::watch;

using raylab::test::freshFolder;

TEST_SUITE("watch rules") {

TEST_CASE("a token is 32 hexadecimal digits, new each time") {
    std::set<std::string> seen;
    for (int k = 0; k < 100; ++k) {
        const std::string token = newToken();
        CHECK(token.size() == 32);
        CHECK(token.find_first_not_of("0123456789abcdef") == std::string::npos);
        seen.insert(token);
    }
    CHECK(seen.size() == 100);
}

TEST_CASE("only the loopback address's own Host header is answered") {
    CHECK(hostAllowed("127.0.0.1:8123", 8123));
    CHECK(hostAllowed("localhost:8123", 8123));
    CHECK_FALSE(hostAllowed("127.0.0.1:8124", 8123)); // another port
    CHECK_FALSE(hostAllowed("127.0.0.1", 8123));
    CHECK_FALSE(hostAllowed("evil.example:8123", 8123)); // DNS rebinding: the attacker's name
    CHECK_FALSE(hostAllowed("localhost.evil.example:8123", 8123));
    CHECK_FALSE(hostAllowed("127.0.0.1.evil.example:8123", 8123));
    CHECK_FALSE(hostAllowed("", 8123));
    CHECK_FALSE(hostAllowed("127.0.0.1:8123:8123", 8123));
}

TEST_CASE("a request is answered under its token only") {
    const std::string token = "0123456789abcdef0123456789abcdef";
    CHECK(underToken("/" + token + "/", token) == std::string());
    CHECK(underToken("/" + token + "/files/report/a.png", token) == std::string("files/report/a.png"));
    CHECK_FALSE(underToken("/" + token, token).has_value()); // the page's links are relative to the folder
    CHECK_FALSE(underToken("/", token).has_value());
    CHECK_FALSE(underToken("/" + token.substr(0, 31) + "0/", token).has_value()); // the last digit wrong
    CHECK_FALSE(underToken("/x" + token.substr(1) + "/", token).has_value());     // the first digit wrong
    CHECK_FALSE(underToken("//" + token + "/", token).has_value());
    CHECK_FALSE(underToken("/anything/", "").has_value());
}

TEST_CASE("nothing outside the watch's folder is served") {
    const fs::path root = freshFolder("watch-root");
    const fs::path outside = freshFolder("watch-outside");
    raylab::writeFileAtomically(root / "report" / "images" / "a.png", "png");
    raylab::writeFileAtomically(root / ".hidden", "secret");
    raylab::writeFileAtomically(outside / "secret.txt", "secret");
    fs::create_symlink(outside / "secret.txt", root / "link.txt");
    fs::create_directory_symlink(outside, root / "linked");

    CHECK(servedFile(root, "report/images/a.png") == root / "report" / "images" / "a.png");
    const std::string besideRoot = "../" + outside.filename().string() + "/secret.txt";
    CHECK_FALSE(servedFile(root, besideRoot).has_value());
    CHECK_FALSE(servedFile(root, "report/../" + besideRoot).has_value());
    CHECK_FALSE(servedFile(root, (outside / "secret.txt").string()).has_value()); // absolute
    CHECK_FALSE(servedFile(root, "link.txt").has_value());                         // a link to a file outside
    CHECK_FALSE(servedFile(root, "linked/secret.txt").has_value());                // through a linked folder
    CHECK_FALSE(servedFile(root, ".hidden").has_value());
    CHECK_FALSE(servedFile(root, "report").has_value()); // a folder
    CHECK_FALSE(servedFile(root, "report/images/").has_value());
    CHECK_FALSE(servedFile(root, "report\\images\\a.png").has_value());
    CHECK_FALSE(servedFile(root, std::string("report/images/a.png\0.txt", 24)).has_value());
    CHECK_FALSE(servedFile(root, "missing.png").has_value());
    CHECK_FALSE(servedFile(root, "").has_value());
}

} // TEST_SUITE

TEST_SUITE("watch parts") {

TEST_CASE("compiler errors: file, line, column and message, each once, relative to the tree") {
    const std::string output = "[ 50%] Building CXX object ...\n"
                               "/src/tree/labs/lab3_sphere/sphere_geometry.cpp:23:12: error: 'nromal' was not declared in this scope\n"
                               "   23 |     return nromal;\n"
                               "/src/tree/labs/lab3_sphere/sphere_geometry.cpp:23:12: error: 'nromal' was not declared in this scope\n"
                               "/src/tree/labs/lab3_sphere/sphere_geometry.cpp:30:1: warning: no return statement\n"
                               "C:\\\\tp\\\\labs\\\\lab2.cpp(12,5): error C2065: 'x': undeclared identifier\r\n"
                               "gmake[2]: *** [framework/CMakeFiles/x.dir/build.make:76: x.o] Error 1\n"
                               // The student's `#error x:99999999999:1: error: y`, echoed under its error:
                               // that line's number does not fit an int, and is no error of its own.
                               "    7 | #error x:99999999999:1: error: y\n";
    const std::vector<CompilerError> errors = compilerErrors(output, "/src/tree");
    REQUIRE(errors.size() == 2);
    CHECK(errors[0].file == "labs/lab3_sphere/sphere_geometry.cpp");
    CHECK(errors[0].line == 23);
    CHECK(errors[0].column == 12);
    CHECK(errors[0].message == "'nromal' was not declared in this scope");
    CHECK(errors[1].line == 12);
    CHECK(errors[1].column == 5);
    CHECK(errors[1].message == "C2065: 'x': undeclared identifier");
    CHECK(compilerErrors("[100%] Built target raylab\n", "/src/tree").empty());
}

TEST_CASE("compiler errors: a file named relative to the compiler's folder in the build (ccache's base_dir) is the tree's") {
    const fs::path tree = raylab::test::freshFolder("raylab-watch-relative-errors");
    fs::create_directories(tree / "labs/lab3_sphere");
    std::ofstream(tree / "labs/lab3_sphere/sphere_geometry.cpp") << "// the student's file\n";
    const std::vector<CompilerError> errors =
        compilerErrors("../../labs/lab3_sphere/sphere_geometry.cpp:7:3: error: expected ';'\n"
                       "../../nowhere/other.cpp:1:1: error: not in the tree\n",
                       tree);
    REQUIRE(errors.size() == 2);
    CHECK(errors[0].file == "labs/lab3_sphere/sphere_geometry.cpp");
    CHECK(errors[0].line == 7);
    CHECK(errors[1].file == "../../nowhere/other.cpp"); // as the compiler said it: no such file in the tree
}

TEST_CASE("the long poll: a newer version at once, the same one after the wait, everything when stopping") {
    PageState page;
    CHECK(page.after(0, std::chrono::milliseconds(0)) == "{}");
    page.publish(R"({"phase":"building"})");
    CHECK(page.version() == 1);
    CHECK(page.after(0, std::chrono::hours(1)) == R"({"version":1,"phase":"building"})"); // newer: no wait
    page.publish("{}");
    CHECK(page.after(1, std::chrono::hours(1)) == R"({"version":2})");
    // A waiter for a version not there yet is woken by the next publication.
    std::string seen;
    std::thread waiter([&] { seen = page.after(2, std::chrono::hours(1)); });
    page.publish(R"({"phase":"ready"})");
    waiter.join();
    CHECK(seen == R"({"version":3,"phase":"ready"})");
    // Stopping wakes every waiter, however long it meant to wait.
    std::thread stopped([&] { seen = page.after(3, std::chrono::hours(1)); });
    page.stop();
    stopped.join();
    CHECK(seen == R"({"version":3,"phase":"ready"})");
}

TEST_CASE("while the latest save does not compile, the last good grade is marked stale, in English and in French") {
    const std::string graded = R"({"figures":[{"id":"lab3_cosine","passed":true}],"checks":[{"name":"a check","passed":true}]})";
    const fs::path tree = "/tree";
    const std::string error = "/tree/labs/lab3_sphere/sphere_geometry.cpp:12:5: error: 'nowhere' was not declared in this scope\n";
    PageFacts facts{3, "build_failed", {"labs/lab3_sphere/sphere_geometry.cpp"}, error, tree};
    auto failed = nlohmann::json::parse(pageDocument(graded, facts));
    CHECK(failed["stale"] == true);
    CHECK(failed["figures"][0]["stale"] == true);
    CHECK(failed["figures"][0]["passed"] == true); // the verdict kept, marked
    CHECK(failed["checks"][0]["stale"] == true);
    REQUIRE(failed["build"]["errors"].size() == 1);
    CHECK(failed["build"]["errors"][0]["file"] == "labs/lab3_sphere/sphere_geometry.cpp");
    CHECK(failed["words"]["stale"] == "stale");
    // Still stale while the next save builds, until one compiles.
    facts.phase = "building";
    CHECK(nlohmann::json::parse(pageDocument(graded, facts))["figures"][0]["stale"] == true);
    facts.buildOutput.clear();
    facts.phase = "ready";
    const auto compiled = nlohmann::json::parse(pageDocument(graded, facts));
    CHECK(compiled["stale"] == false);
    CHECK(compiled["figures"][0]["stale"] == false);
    CHECK(compiled["checks"][0]["stale"] == false);
    CHECK(compiled["build"]["errors"].empty());
    raylab::setLanguage(raylab::Language::Fr);
    const auto french = nlohmann::json::parse(pageDocument(graded, facts));
    raylab::setLanguage(raylab::Language::En);
    CHECK(french["words"]["stale"] == "périmé");
    CHECK(french["words"]["stale_banner"].get<std::string>().find("ne compile pas\u00A0:") != std::string::npos);
    // A file named with bytes that are not UTF-8 (`#line 1 "\xff<b>.cpp"`) and a saved file so named:
    // shown as their bytes, never an exception.
    facts.buildOutput = "\xff<b>.cpp:1:1: error: y\n";
    facts.changed = {"labs/lab3_sphere/\xe9t\xe9.cpp"};
    const auto named = nlohmann::json::parse(pageDocument(graded, facts));
    REQUIRE(named["build"]["errors"].size() == 1);
    CHECK(named["build"]["errors"][0]["file"] == "\\xFF<b>.cpp");
    CHECK(named["changed"][0] == "labs/lab3_sphere/\\xE9t\\xE9.cpp");
    facts.buildOutput.clear();
    facts.changed.clear();
    // A grade that is no JSON object (it never is) makes a page, not an exception.
    CHECK(nlohmann::json::parse(pageDocument("not json", facts))["stale"] == false);
}

TEST_CASE("a problem that stopped a refresh is shown on the page, made printable, in place of the grade") {
    PageState page;
    std::mutex agents;
    WatchSettings settings;
    settings.lab = 3;
    settings.out = freshFolder("watch-problem");
    settings.sourceDir = "/tree";
    WatchSession session(settings, page, agents);
    session.showProblem("cannot read labs/lab3_sphere/\xff.cpp\x1b[2J");
    const auto shown = nlohmann::json::parse(page.after(0, std::chrono::milliseconds(0)));
    CHECK(shown["phase"] == "ready");
    CHECK(shown["lab"] == 3);
    REQUIRE(shown["problems"].size() == 1);
    CHECK(shown["problems"][0] == "cannot read labs/lab3_sphere/\\xFF.cpp\\x1B[2J");
}

TEST_CASE("the files that count as code") {
    CHECK(isWatchedFile("labs/lab3_sphere/sphere_geometry.cpp"));
    CHECK(isWatchedFile("labs/lab3_sphere/lab.toml"));
    CHECK_FALSE(isWatchedFile("labs/lab3_sphere/README.md"));
    CHECK_FALSE(isWatchedFile("labs/lab3_sphere/figure.png"));
    CHECK_FALSE(isWatchedFile("labs/lab3_sphere/.sphere_geometry.cpp.swp"));
    CHECK_FALSE(isWatchedFile("labs/lab3_sphere/sphere_geometry.cpp~"));
    CHECK(isWatchedFile("labs/lab6_shadows/point_light_integrator.h"));
    CHECK(isWatchedFile("labs/lab3_sphere/scenes/lab3_cosine.toml"));
}

TEST_CASE("editors' temporary and backup files are not code") {
    for (const char* name : {"sedvVUgJG", "sedAb12Cd", ".sphere_geometry.cpp.swp", ".sphere_geometry.cpp.swx", "sphere_geometry.cpp.swp",
                             "4913", "sphere_geometry.cpp~", "#sphere_geometry.cpp#", ".#sphere_geometry.cpp", "sphere_geometry.cpp.tmp",
                             "sphere_geometry.cpp.orig", "sphere_geometry.cpp.rej", "sphere_geometry.cpp.bak",
                             "sphere_geometry.cpp.kate-swp", "sphere_geometry.cpp___jb_tmp___", "my notes.cpp", ".cpp", "Makefile"}) {
        CAPTURE(name);
        CHECK_FALSE(isWatchedFile(fs::path("labs/lab3_sphere") / name));
    }
}

TEST_CASE("a watcher lists a save renamed over a lab file, never the editor's files around it") {
    const fs::path folder = freshFolder("watch-editors");
    raylab::writeFileAtomically(folder / "sphere.cpp", "int a;");
    FileWatcher watcher({folder});
    // sed -i: a temporary file written, then renamed over the lab file; vim: its 4913 probe and its swap file.
    raylab::writeFileAtomically(folder / "4913", "");
    raylab::writeFileAtomically(folder / ".sphere.cpp.swp", "swap");
    raylab::writeFileAtomically(folder / "sphere.cpp~", "int a;");
    raylab::writeFileAtomically(folder / "sedvVUgJG", "int b;");
    fs::rename(folder / "sedvVUgJG", folder / "sphere.cpp");
    std::vector<fs::path> changed;
    for (int k = 0; k < 50 && changed.empty(); ++k) changed = watcher.changes(std::chrono::milliseconds(200));
    for (auto more = watcher.changes(std::chrono::milliseconds(100)); !more.empty(); more = watcher.changes(std::chrono::milliseconds(100)))
        changed.insert(changed.end(), more.begin(), more.end());
    CHECK(changed == std::vector<fs::path>{folder / "sphere.cpp"});
}

// Both watchers: inotify (Linux) and the portable polling one (RAYLAB_WATCH_POLL, as elsewhere).
void seesSaves(bool polling) {
    if (polling) setenv("RAYLAB_WATCH_POLL", "1", 1);
    else unsetenv("RAYLAB_WATCH_POLL");
    const fs::path folder = freshFolder(polling ? "watch-polled" : "watch-notified");
    raylab::writeFileAtomically(folder / "lab3" / "sphere.cpp", "int a;");
    FileWatcher watcher({folder});
    unsetenv("RAYLAB_WATCH_POLL");
    CHECK(std::string(watcher.how()) == (polling ? "polling" : "inotify"));
    CHECK(watcher.changes(std::chrono::milliseconds(0)).empty());
    // Polling sees a change of time: a save in the same clock tick as the snapshot would not be one.
    std::this_thread::sleep_for(std::chrono::milliseconds(polling ? 20 : 0));
    raylab::writeFileAtomically(folder / "lab3" / "sphere.cpp", "int b;");
    raylab::writeFileAtomically(folder / "lab3" / "README.md", "a handout");
    std::vector<fs::path> changed;
    for (int k = 0; k < 50 && changed.empty(); ++k) changed = watcher.changes(std::chrono::milliseconds(200));
    REQUIRE(changed.size() == 1);
    CHECK(changed.front() == folder / "lab3" / "sphere.cpp");
    // A folder made after the watcher started is watched too.
    raylab::writeFileAtomically(folder / "lab3" / "new" / "more.cpp", "int c;");
    changed.clear();
    for (int k = 0; k < 50 && changed.empty(); ++k) changed = watcher.changes(std::chrono::milliseconds(200));
    CHECK(std::find(changed.begin(), changed.end(), folder / "lab3" / "new" / "more.cpp") != changed.end());
}

#ifdef __linux__
TEST_CASE("inotify sees a save, not a handout's") { seesSaves(false); }
#endif
TEST_CASE("polling sees a save, not a handout's") { seesSaves(true); }

} // TEST_SUITE

TEST_SUITE("watch server") {

// The server on a free port of 127.0.0.1, serving `root`, asked over HTTP as a browser asks it.
struct Served {
    raylab::watch::PageState page;
    raylab::watch::WatchServer server;
    int port;
    std::thread serving;
    // The inspector answers with what it was asked, unless the test gives its own.
    explicit Served(const fs::path& root, Inspector inspector = [](const std::string& figure, int x, int y) {
        return figure + " " + std::to_string(x) + " " + std::to_string(y);
    })
        : server(page, root, "0123456789abcdef0123456789abcdef", std::move(inspector)), port(server.bind(0)),
          serving([this] { server.serve(); }) {}
    ~Served() {
        server.stop();
        serving.join();
    }
    // GET `path` with the Host header `host` (this server's own when empty): the status and the body.
    std::pair<int, std::string> get(const std::string& path, std::string host = "") {
        httplib::Client client("127.0.0.1", port);
        if (host.empty()) host = "127.0.0.1:" + std::to_string(port);
        const auto answer = client.Get(path.c_str(), httplib::Headers{{"Host", host}});
        return answer ? std::pair{answer->status, answer->body} : std::pair{-1, std::string()};
    }
};

TEST_CASE("the page, its files and the inspector under the token, with the right Host header only") {
    const fs::path root = freshFolder("watch-served");
    raylab::writeFileAtomically(root / "report" / "images" / "a.png", "not really a png");
    raylab::writeFileAtomically(fs::path(root).concat("-secret.txt"), "secret");
    Served served(root);
    const std::string at = "/0123456789abcdef0123456789abcdef/";
    CHECK(served.server.address() == "http://127.0.0.1:" + std::to_string(served.port) + at);
    const auto page = served.get(at);
    CHECK(page.first == 200);
    CHECK(page.second.find("<script src=\"watch.js\"") != std::string::npos);
    CHECK(served.get(at + "watch.js").first == 200);
    CHECK(served.get(at + "files/report/images/a.png") == std::pair{200, std::string("not really a png")});
    CHECK(served.get(at + "inspect?figure=lab3_cosine&x=3&y=4") == std::pair{200, std::string("lab3_cosine 3 4")});
    CHECK(served.get(at, "localhost:" + std::to_string(served.port)).first == 200);
    // Another name in Host (DNS rebinding), another port, no token, another token, outside the folder.
    CHECK(served.get(at, "evil.example:" + std::to_string(served.port)).first == 403);
    CHECK(served.get(at + "files/report/images/a.png", "evil.example").first == 403);
    CHECK(served.get("/").first == 404);
    CHECK(served.get("/0123456789abcdef0123456789abcdee/").first == 404);
    CHECK(served.get(at + "files/../" + root.filename().string() + "-secret.txt").first == 404);
    CHECK(served.get(at + "files/%2e%2e/" + root.filename().string() + "-secret.txt").first == 404);
    CHECK(served.get(at + "nothing").first == 404);
    httplib::Client client("127.0.0.1", served.port);
    const auto posted = client.Post(at.c_str(), "x", "text/plain");
    REQUIRE(posted);
    CHECK(posted->status == 405);
}

TEST_CASE("the state: at once without a version, when a newer one is published with one") {
    Served served(freshFolder("watch-state"));
    const std::string at = "/0123456789abcdef0123456789abcdef/";
    CHECK(served.get(at + "state") == std::pair{200, std::string("{}")});
    served.page.publish(R"({"phase":"ready"})");
    CHECK(served.get(at + "state?since=0") == std::pair{200, std::string(R"({"version":1,"phase":"ready"})")});
    std::pair<int, std::string> waited;
    std::thread poll([&] { waited = served.get(at + "state?since=1"); });
    served.page.publish(R"({"phase":"building"})");
    poll.join();
    CHECK(waited == std::pair{200, std::string(R"({"version":2,"phase":"building"})")});
}

TEST_CASE("an answer that fails is a 500 with the page's words, never the exception's text; the server goes on") {
    Served served(freshFolder("watch-failing"), [](const std::string& figure, int, int) -> std::string {
        throw std::runtime_error("secret detail of " + figure);
    });
    const std::string at = "/0123456789abcdef0123456789abcdef/";
    httplib::Client client("127.0.0.1", served.port);
    const auto answer = client.Get((at + "inspect?figure=%FF&x=1&y=2").c_str());
    REQUIRE(answer);
    CHECK(answer->status == 500);
    CHECK(answer->body == raylab::tr("watch.not_answered"));
    for (const auto& [name, value] : answer->headers) CHECK_MESSAGE(value.find("secret") == std::string::npos, name);
    CHECK(served.get(at + "state").first == 200); // still serving
}

#ifndef _WIN32
// A client that began its request and sends one more header line every 200 ms, never ending it (as a
// slow or hostile client does), until `stop`.
void dripRequest(int port, const std::atomic<bool>& stop) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(std::uint16_t(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (fd < 0 || ::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) return;
    const std::string start = "GET /0123456789abcdef0123456789abcdef/ HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\n";
    ::send(fd, start.data(), start.size(), MSG_NOSIGNAL);
    while (!stop) {
        ::send(fd, "X-Slow: 1\r\n", 11, MSG_NOSIGNAL);
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
    ::close(fd);
}

// A connection to the server on `port`, sending bytes as a client may, raw.
struct RawClient {
    int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    explicit RawClient(int port) {
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_port = htons(std::uint16_t(port));
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        const timeval timeout{10, 0}; // a test that fails fails in 10 s, it does not hang
        ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
        ::setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &timeout, sizeof timeout);
        const int buffer = 64 * 1024; // what the client holds back itself
        ::setsockopt(fd, SOL_SOCKET, SO_SNDBUF, &buffer, sizeof buffer);
        REQUIRE(::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0);
    }
    ~RawClient() { ::close(fd); }
    RawClient(const RawClient&) = delete;
    RawClient& operator=(const RawClient&) = delete;
    // The bytes the server took of `bytes` before it closed the connection (all of them if it did not).
    std::size_t send(const std::string& bytes) const {
        std::size_t sent = 0;
        while (sent < bytes.size()) {
            const auto n = ::send(fd, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
            if (n <= 0) break;
            sent += std::size_t(n);
        }
        return sent;
    }
    // What the server answers, up to its closing the connection.
    std::string answer() const {
        std::string got;
        char buffer[4096];
        for (ssize_t n; (n = ::recv(fd, buffer, sizeof buffer, 0)) > 0;) got.append(buffer, std::size_t(n));
        return got;
    }
};

// A request for the page with its Host header, then `headers` more headers "X-Header-k: k", then
// `lastHeader` (when not empty) and the empty line.
std::string pageRequest(int port, int headers, const std::string& lastHeader = "") {
    std::string request = "GET /0123456789abcdef0123456789abcdef/ HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\n";
    for (int k = 0; k < headers; ++k) request += "X-Header-" + std::to_string(k) + ": " + std::to_string(k) + "\r\n";
    if (!lastHeader.empty()) request += lastHeader + "\r\n";
    return request + "\r\n";
}

// A request for the page whose head (request line, headers and the empty line) is `bytes` long, in
// header lines of at most 8000 bytes (httplib's own limit for one is 8192).
std::string pageRequestOfSize(int port, std::size_t bytes) {
    std::string request = pageRequest(port, 0);
    request.resize(request.size() - 2); // without the empty line yet
    while (request.size() + 2 < bytes) {
        const std::size_t line = std::min<std::size_t>(8000, bytes - 2 - request.size());
        REQUIRE(line >= 12); // "X-Fill: " + at least 2 + "\r\n"
        const std::size_t next = bytes - 2 - request.size() - line; // what a next line would have
        const std::size_t take = next > 0 && next < 12 ? line - 12 : line;
        request += "X-Fill: " + std::string(take - 10, 'a') + "\r\n";
    }
    return request + "\r\n";
}

std::string statusLine(const std::string& answer) { return answer.substr(0, answer.find("\r\n")); }

TEST_CASE("a request's head past its limits is refused before it is kept: 100 lines, 64 KB, 5 s") {
    Served served(freshFolder("watch-heads"));
    // The request line and 99 headers (Host and 98 others): answered; one header more: refused.
    const auto asked = [&](const std::string& request) {
        const RawClient client(served.port);
        client.send(request);
        return statusLine(client.answer());
    };
    CHECK(asked(pageRequest(served.port, 98)) == "HTTP/1.1 200 OK");
    CHECK(asked(pageRequest(served.port, 99)) == "HTTP/1.1 431 Request Header Fields Too Large");
    // Bytes: a head of exactly 64 KB is read, one byte more is refused.
    REQUIRE(pageRequestOfSize(served.port, raylab::watch::kMaxHeadBytes).size() == raylab::watch::kMaxHeadBytes);
    CHECK(asked(pageRequestOfSize(served.port, raylab::watch::kMaxHeadBytes)) == "HTTP/1.1 200 OK");
    CHECK(asked(pageRequestOfSize(served.port, raylab::watch::kMaxHeadBytes + 1)) == "HTTP/1.1 431 Request Header Fields Too Large");
    {   // 30 MB of headers and no token: the server stops taking them (it took them all before).
        const RawClient client(served.port);
        std::string flood = "GET / HTTP/1.1\r\n";
        while (flood.size() < 30'000'000) flood += "X-Flood: " + std::string(1000, 'f') + "\r\n";
        CHECK(client.send(flood) < 12'000'000); // the limit, its drain and the sockets' buffers
    }
    {   // A head sent one line every 200 ms: refused after 5 s, the connection closed.
        const RawClient client(served.port);
        const auto start = std::chrono::steady_clock::now();
        client.send("GET /0123456789abcdef0123456789abcdef/ HTTP/1.1\r\n");
        std::string answer;
        std::atomic<bool> answered{false};
        std::thread reading([&] {
            answer = client.answer();
            answered = true;
        });
        while (!answered && std::chrono::steady_clock::now() - start < std::chrono::seconds(9)) {
            client.send("X-Slow: 1\r\n");
            std::this_thread::sleep_for(std::chrono::milliseconds(200));
        }
        reading.join();
        CHECK(statusLine(answer) == "HTTP/1.1 408 Request Timeout");
        CHECK(std::chrono::steady_clock::now() - start >= raylab::watch::kHeadTime);
    }
    CHECK(served.get("/0123456789abcdef0123456789abcdef/").first == 200); // still serving
}

TEST_CASE("the page answers beside 10 slow clients and 8 tabs waiting for a change") {
    Served served(freshFolder("watch-busy"));
    served.page.publish(R"({"phase":"ready"})");
    const std::string at = "/0123456789abcdef0123456789abcdef/";
    std::atomic<bool> stop{false};
    std::vector<std::thread> clients;
    for (int k = 0; k < 10; ++k) clients.emplace_back([&] { dripRequest(served.port, stop); });
    std::atomic<int> polled{0};
    for (int k = 0; k < 8; ++k) // each tab waits for the version after 1: up to 20 s
        clients.emplace_back([&] {
            if (served.get(at + "state?since=1").first == 200) ++polled;
        });
    std::this_thread::sleep_for(std::chrono::milliseconds(500)); // all of them connected and waiting
    // The page and its state while they all wait: within 10 s, half the long polls' 20 (not a
    // benchmark: an answer that waits for them is no answer).
    httplib::Client client("127.0.0.1", served.port);
    client.set_read_timeout(10, 0);
    client.set_connection_timeout(10, 0);
    const httplib::Headers host{{"Host", "127.0.0.1:" + std::to_string(served.port)}};
    const auto page = client.Get(at.c_str(), host);
    CHECK((page && page->status == 200));
    const auto state = client.Get((at + "state").c_str(), host);
    CHECK((state && state->body == R"({"version":1,"phase":"ready"})"));
    CHECK(polled == 0); // the tabs were still waiting
    served.page.publish(R"({"phase":"building"})"); // wakes the tabs
    stop = true;
    for (std::thread& t : clients) t.join();
    CHECK(polled == 8);
}
#endif

TEST_CASE("a port already taken is said, naming it, in the language chosen (not the test's locale)") {
    Served first(freshFolder("watch-port"));
    raylab::watch::PageState page;
    raylab::watch::WatchServer second(page, freshFolder("watch-port2"), "t", nullptr);
    const raylab::Language before = raylab::language();
    const auto said = [&](raylab::Language language) {
        raylab::setLanguage(language);
        std::string what;
        try {
            second.bind(first.port);
        } catch (const std::runtime_error& e) {
            what = e.what();
        }
        return what;
    };
    const std::string address = "127.0.0.1:" + std::to_string(first.port);
    CHECK(said(raylab::Language::En).find("cannot listen on " + address) != std::string::npos);
    CHECK(said(raylab::Language::Fr).find("impossible d'écouter sur " + address) != std::string::npos);
    raylab::setLanguage(before);
}

} // TEST_SUITE
