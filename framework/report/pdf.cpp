#include "report/pdf.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <fstream>
#include <random>
#include <spawn.h>
#include <stdexcept>
#include <string>
#include <thread>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace raylab::report {

namespace fs = std::filesystem;

namespace {

// Runs `args` (args[0] the program), its output to /dev/null, for two minutes at most, and returns
// its exit status. An argument vector, no shell: a path with spaces or quotes stays one argument.
int runQuietly(const std::vector<std::string>& args) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    const int error = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0) throw std::runtime_error("cannot run " + args[0]);
    int status = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    for (pid_t done = 0; done != pid;) { // a browser that hangs is stopped, not waited for
        done = waitpid(pid, &status, WNOHANG);
        if (done < 0 && errno != EINTR) throw std::runtime_error("lost " + args[0] + " while it ran");
        if (done == 0 && std::chrono::steady_clock::now() > deadline) kill(pid, SIGKILL);
        if (done == 0) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

bool isPdf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    char head[5] = {};
    in.read(head, 4);
    return std::string(head) == "%PDF";
}

} // namespace

std::optional<fs::path> findChromium() {
    const char* path = std::getenv("PATH");
    std::string folders = path ? path : "/usr/bin:/bin";
    for (std::size_t begin = 0, end = 0; begin <= folders.size(); begin = end + 1) {
        end = folders.find(':', begin);
        if (end == std::string::npos) end = folders.size();
        for (const char* name : {"chromium", "chromium-browser", "google-chrome", "google-chrome-stable"}) {
            const fs::path candidate = fs::path(folders.substr(begin, end - begin)) / name;
            std::error_code e;
            if (fs::is_regular_file(candidate, e) && access(candidate.c_str(), X_OK) == 0) return candidate;
        }
    }
    return std::nullopt;
}

void printToPdf(const fs::path& chromium, const fs::path& html, const fs::path& pdf) {
    std::random_device random;
    const fs::path profile = fs::temp_directory_path() / ("raylab-chromium-" + std::to_string(random()));
    const fs::path partial = pdf.string() + ".partial";
    fs::remove(partial);
    const int status = runQuietly({chromium.string(), "--headless", "--no-sandbox", "--disable-gpu",
                                   "--disable-background-networking", "--disable-component-update", "--no-first-run",
                                   "--user-data-dir=" + profile.string(), "--no-pdf-header-footer",
                                   "--print-to-pdf=" + partial.string(), "file://" + fs::absolute(html).string()});
    std::error_code ignored;
    fs::remove_all(profile, ignored);
    if (status != 0 || !isPdf(partial)) {
        fs::remove(partial, ignored);
        throw std::runtime_error(chromium.string() + " did not print " + html.string() + " (exit status " +
                                 std::to_string(status) + ")");
    }
    fs::rename(partial, pdf); // whole or nothing
}

} // namespace raylab::report
