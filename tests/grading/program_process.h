#pragma once
// The tests' way to run raylab as a shell would, and to stop it as Ctrl-C would: a program started
// with an argument vector in a process group of its own, its output in a file, waited for later.
// POSIX only.

#include "grader/sandbox/process.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ; // declared by unistd.h on Linux only

namespace raylab::test {

struct ProgramProcess {
    pid_t pid = -1;
    std::filesystem::path output; // its stdout and stderr

    // Waits for it: its exit status, 128 + the signal when one ended it.
    int finish() const {
        int status = 0;
        while (waitpid(pid, &status, 0) < 0)
            if (errno != EINTR) return -1;
        return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }

    // As finish(), but kills it and returns -1 when it is still running after `seconds`.
    int finishWithin(double seconds) const {
        const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        int status = 0;
        while (waitpid(pid, &status, WNOHANG) == 0) {
            if (std::chrono::steady_clock::now() > end) {
                kill(-pid, SIGKILL);
                waitpid(pid, &status, 0);
                return -1;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }

    std::string text() const {
        std::ifstream in(output, std::ios::binary);
        std::stringstream all;
        all << in.rdbuf();
        return all.str();
    }
};

// Starts `program args...`. `fileSizeLimit` > 0: the files it writes stop at that many bytes and a
// longer write fails (EFBIG) instead of killing it, as on a nearly full disk. `environment`: "NAME=value"
// entries that replace the variables of those names in its environment (ours otherwise).
inline ProgramProcess startProgram(const std::filesystem::path& program, const std::vector<std::string>& args,
                                   const std::filesystem::path& output, long fileSizeLimit = 0,
                                   const std::vector<std::string>& environment = {}) {
    std::vector<std::string> argv{program.string()};
    argv.insert(argv.end(), args.begin(), args.end());
    const std::vector<char*> cargs = grader::argumentPointers(argv);
    std::vector<std::string> env = environment;
    const auto named = [](const std::string& entry) { return entry.substr(0, entry.find('=') + 1); };
    for (char** e = environ; *e; ++e) {
        const std::string entry = *e;
        if (std::none_of(environment.begin(), environment.end(), [&](const std::string& given) { return named(given) == named(entry); }))
            env.push_back(entry);
    }
    const std::vector<char*> cenv = grader::argumentPointers(env);
    std::fflush(nullptr);
    const pid_t pid = fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        setpgid(0, 0);
        const int out = open(output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int null = open("/dev/null", O_RDONLY);
        if (out < 0 || null < 0) _exit(126);
        dup2(null, 0);
        dup2(out, 1);
        dup2(out, 2);
        if (fileSizeLimit > 0) {
            std::signal(SIGXFSZ, SIG_IGN); // kept across exec
            rlimit limit{rlim_t(fileSizeLimit), rlim_t(fileSizeLimit)};
            setrlimit(RLIMIT_FSIZE, &limit);
        }
        execve(cargs[0], cargs.data(), cenv.data());
        _exit(127);
    }
    setpgid(pid, pid);
    return {pid, output};
}

} // namespace raylab::test
