#pragma once
// Headless chromium driven as a user drives a browser (POSIX): the DevTools protocol over the pipe
// that --remote-debugging-pipe opens (descriptors 3 and 4, one JSON message each, ended by a NUL):
// open a page, read it with a script, click at a point of the screen, take a screenshot.

#include "grader/protocol/protocol.h"

#include <nlohmann/json.hpp>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace raylab::test {

class HeadlessChromium {
public:
    // Starts `program` with a profile in `profile` (created, emptied) and a window of that size.
    HeadlessChromium(const std::filesystem::path& program, const std::filesystem::path& profile, int width, int height) {
        std::filesystem::remove_all(profile);
        std::filesystem::create_directories(profile);
        int toBrowser[2], fromBrowser[2];
        if (pipe(toBrowser) != 0 || pipe(fromBrowser) != 0) throw std::runtime_error("pipe");
        std::vector<std::string> args{program.string(), "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
                                      "--disable-background-networking", "--disable-component-update", "--disable-sync",
                                      "--remote-debugging-pipe", "--user-data-dir=" + profile.string(),
                                      "--window-size=" + std::to_string(width) + "," + std::to_string(height), "about:blank"};
        m_pid = fork();
        if (m_pid < 0) throw std::runtime_error("fork");
        if (m_pid == 0) {
            // Out of the way of 3 and 4 first, then onto them.
            const int in = fcntl(toBrowser[0], F_DUPFD, 10), out = fcntl(fromBrowser[1], F_DUPFD, 10);
            dup2(in, 3);
            dup2(out, 4);
            const int null = ::open("/dev/null", O_WRONLY);
            dup2(null, 1);
            dup2(null, 2);
            for (int fd = 5; fd < 256; ++fd) close(fd);
            std::vector<char*> argv;
            for (std::string& a : args) argv.push_back(a.data());
            argv.push_back(nullptr);
            execv(argv[0], argv.data());
            _exit(127);
        }
        close(toBrowser[0]);
        close(fromBrowser[1]);
        m_write = toBrowser[1];
        m_read = fromBrowser[0];
        // The page's own session: commands of the Page, Runtime and Input domains go to it.
        const nlohmann::json targets = call("Target.getTargets");
        std::string page;
        for (const auto& t : targets["targetInfos"])
            if (t["type"] == "page") page = t["targetId"];
        if (page.empty()) page = call("Target.createTarget", {{"url", "about:blank"}})["targetId"];
        m_session = call("Target.attachToTarget", {{"targetId", page}, {"flatten", true}})["sessionId"];
        call("Page.enable");
    }

    ~HeadlessChromium() {
        close(m_write);
        close(m_read);
        kill(m_pid, SIGKILL);
        waitpid(m_pid, nullptr, 0);
    }
    HeadlessChromium(const HeadlessChromium&) = delete;
    HeadlessChromium& operator=(const HeadlessChromium&) = delete;

    void open(const std::string& address) { call("Page.navigate", {{"url", address}}); }

    // The value of a script's expression in the page (a promise awaited); throws with its exception.
    nlohmann::json evaluate(const std::string& expression) {
        const nlohmann::json r =
            call("Runtime.evaluate", {{"expression", expression}, {"returnByValue", true}, {"awaitPromise", true}});
        if (r.contains("exceptionDetails")) throw std::runtime_error("in the page: " + r["exceptionDetails"].dump());
        return r["result"].value("value", nlohmann::json());
    }

    // Evaluates `expression` until it is true, every 50 ms for at most `seconds`; false when it never
    // was. An expression that throws (the page still loading: no body yet) is not true yet.
    bool waitFor(const std::string& expression, double seconds = 120.) {
        for (double waited = 0.; waited < seconds; waited += 0.05) {
            if (evaluate("(() => { try { return Boolean(" + expression + "); } catch (e) { return false; } })()") == true)
                return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        return false;
    }

    // A click of the left button at (x, y) of the page's viewport, as a mouse makes it.
    void click(double x, double y) {
        for (const char* type : {"mouseMoved", "mousePressed", "mouseReleased"})
            call("Input.dispatchMouseEvent",
                 {{"type", type}, {"x", x}, {"y", y}, {"button", "left"}, {"clickCount", std::string(type) == "mouseMoved" ? 0 : 1}});
    }

    void press(const std::string& key) {
        call("Input.dispatchKeyEvent", {{"type", "keyDown"}, {"key", key}, {"text", key}});
        call("Input.dispatchKeyEvent", {{"type", "keyUp"}, {"key", key}});
    }

    // The window's view of the page as a PNG's bytes.
    std::vector<std::uint8_t> screenshot() {
        const nlohmann::json shot = call("Page.captureScreenshot", {{"format", "png"}});
        return grader::protocol::base64Decode(shot["data"].get<std::string>()).value();
    }

private:
    nlohmann::json call(const std::string& method, const nlohmann::json& params = nlohmann::json::object()) {
        const int id = ++m_lastId;
        nlohmann::json message{{"id", id}, {"method", method}, {"params", params}};
        if (!m_session.empty() && !method.starts_with("Target.")) message["sessionId"] = m_session;
        const std::string bytes = message.dump() + '\0';
        for (std::size_t at = 0; at < bytes.size();) {
            const ssize_t n = write(m_write, bytes.data() + at, bytes.size() - at);
            if (n <= 0) throw std::runtime_error("chromium stopped reading");
            at += std::size_t(n);
        }
        for (;;) { // events come in between: the answer is the message with our id
            const nlohmann::json answer = nlohmann::json::parse(nextMessage());
            if (answer.value("id", 0) != id) continue;
            if (answer.contains("error")) throw std::runtime_error(method + ": " + answer["error"].dump());
            return answer["result"];
        }
    }

    std::string nextMessage() {
        for (;;) {
            if (const std::size_t end = m_buffer.find('\0'); end != std::string::npos) {
                std::string message = m_buffer.substr(0, end);
                m_buffer.erase(0, end + 1);
                return message;
            }
            char chunk[65536];
            const ssize_t n = read(m_read, chunk, sizeof chunk);
            if (n <= 0) throw std::runtime_error("chromium closed its pipe");
            m_buffer.append(chunk, std::size_t(n));
        }
    }

    pid_t m_pid = -1;
    int m_write = -1, m_read = -1;
    int m_lastId = 0;
    std::string m_session, m_buffer;
};

} // namespace raylab::test
