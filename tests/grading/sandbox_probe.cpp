// A stand-in agent that misbehaves as asked (argv[1]), to test the sandbox's limits.
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#include <csignal>
#include <unistd.h>

namespace {

int g_fd = -1;

void report(const std::string& line) {
    const std::string text = line + "\n";
    if (write(g_fd, text.data(), text.size()) < 0) std::exit(3);
}

} // namespace

int main(int argc, char** argv) {
    for (int k = 1; k + 1 < argc; ++k)
        if (std::strcmp(argv[k], "--report-fd") == 0) g_fd = std::atoi(argv[k + 1]);
    if (argc < 2 || g_fd < 0) return 2;
    const std::string mode = argv[1];
    std::printf("{\"kind\":\"done\"}\n"); // fake output on stdout: must be ignored
    std::fflush(stdout);
    if (mode == "report") {
        report(R"({"kind":"hello"})");
        report(R"({"kind":"done"})");
    } else if (mode == "loop") {
        report(R"({"kind":"hello"})");
        std::atomic<unsigned long> spin{0};
        for (;;) spin.fetch_add(1, std::memory_order_relaxed);
    } else if (mode == "silent") {
        close(g_fd);
        pause(); // the pipe is closed, the process lives on
    } else if (mode == "grandchild") {
        if (fork() == 0) pause(); // holds the pipe open after its parent has gone
        report(R"({"kind":"hello"})");
        return 0;
    } else if (mode == "crash") {
        report(R"({"kind":"hello"})");
        std::raise(SIGSEGV);
    } else if (mode == "spam") {
        std::vector<char> block(1 << 20, 'x');
        for (;;) std::fwrite(block.data(), 1, block.size(), stdout);
    } else if (mode == "alloc") {
        std::vector<std::vector<char>> hog;
        try {
            for (;;) hog.emplace_back(std::size_t(64) << 20, char(1));
        } catch (const std::bad_alloc&) {
            report(R"({"kind":"refused"})");
        }
    } else if (mode == "cwd") {
        char cwd[4096];
        report(std::string(R"({"kind":"cwd","path":")") + (getcwd(cwd, sizeof cwd) ? cwd : "") + "\"}");
    }
    return 0;
}
#else
int main() { return 2; }
#endif
