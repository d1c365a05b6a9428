// A stand-in agent that misbehaves as asked (argv[1], its argument argv[2]), to test the sandbox.
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>
#include <sstream>
#include <string>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#include <arpa/inet.h>
#include <cerrno>
#include <csignal>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

int g_fd = -1;

void report(const std::string& line) {
    const std::string text = line + "\n";
    if (write(g_fd, text.data(), text.size()) < 0) std::exit(3);
}

[[noreturn]] void spin() {
    std::atomic<unsigned long> counter{0};
    for (;;) counter.fetch_add(1, std::memory_order_relaxed);
}

// Appends a byte to `file` every 20 ms, forever: a test sees that it stopped when the file stops growing.
[[noreturn]] void heartbeat(const char* file) {
    for (;;) {
        const int fd = open(file, O_WRONLY | O_CREAT | O_APPEND, 0644);
        if (fd >= 0) {
            if (write(fd, "x", 1) < 0) _exit(4);
            close(fd);
        }
        usleep(20000);
    }
}

std::string readAll(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return "";
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace

int main(int argc, char** argv) {
    int requestFd = -1;
    for (int k = 1; k + 1 < argc; ++k) {
        if (std::strcmp(argv[k], "--report-fd") == 0) g_fd = std::atoi(argv[k + 1]);
        if (std::strcmp(argv[k], "--request-fd") == 0) requestFd = std::atoi(argv[k + 1]);
    }
    if (argc < 2 || g_fd < 0) return 2;
    const std::string mode = argv[1];
    const std::string arg = argc > 2 ? argv[2] : "";
    std::printf("{\"kind\":\"done\"}\n"); // fake output on stdout: must be ignored
    std::fflush(stdout);
    if (mode == "report") {
        report(R"({"kind":"hello"})");
        report(R"({"kind":"done"})");
    } else if (mode == "loop") {
        report(R"({"kind":"hello"})");
        spin();
    } else if (mode == "silent") {
        close(g_fd);
        pause(); // the pipe is closed, the process lives on
    } else if (mode == "close-and-loop") {
        close(g_fd);
        spin();
    } else if (mode == "grandchild") {
        if (fork() == 0) pause(); // holds the pipe open after its parent has gone
        report(R"({"kind":"hello"})");
        return 0;
    } else if (mode == "busy-children") { // 20 busy children hold the channel; the parent leaves
        for (int k = 0; k < 20; ++k)
            if (fork() == 0) {
                if (k == 0) heartbeat("heartbeat");
                spin();
            }
        report(R"({"kind":"hello"})");
        return 0;
    } else if (mode == "daemon") { // the classic double fork into a session of its own
        if (fork() == 0) {
            setsid();
            if (fork() == 0) {
                close(g_fd);
                heartbeat("heartbeat");
            }
            _exit(0);
        }
        usleep(100000);
        report(R"({"kind":"hello"})");
        return 0;
    } else if (mode == "signal-grader") { // arg: the grader's pid as the test sees it
        const int sent = kill(std::atoi(arg.c_str()), SIGTERM);
        const int parent = kill(getppid(), SIGTERM);
        usleep(200000);
        report(std::string(R"({"kind":"signalled","grader":)") + std::to_string(sent) + ",\"parent\":" +
               std::to_string(parent) + "}");
        report(R"({"kind":"done"})");
    } else if (mode == "connect") { // arg: a port on 127.0.0.1
        const int s = socket(AF_INET, SOCK_STREAM, 0);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_port = htons(std::uint16_t(std::atoi(arg.c_str())));
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        const bool connected = s >= 0 && connect(s, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0;
        if (connected && write(s, "PATH HOME", 9) < 0) return 5;
        report(std::string(R"({"kind":"connect","connected":)") + (connected ? "true" : "false") + "}");
    } else if (mode == "escape") { // arg: a file outside the scratch folder that the grader can read
        const std::string secret = readAll(arg);
        report(std::string(R"({"kind":"read","bytes":)") + std::to_string(secret.size()) + "}");
        std::ofstream("../intruder.txt") << "written beside the scratch folder";
        std::error_code ignored;
        std::filesystem::remove_all(std::filesystem::current_path().parent_path(), ignored);
        report(R"({"kind":"done"})");
    } else if (mode == "privileges") { // arg: a file to read; argv[3]: a folder to write in
        const std::string folder = argc > 3 ? argv[3] : ".";
        const bool root = setuid(0) == 0;
        const int file = open(arg.c_str(), O_RDONLY);
        const int written = open((folder + "/intruder.txt").c_str(), O_WRONLY | O_CREAT, 0644);
        const int inet = socket(AF_INET, SOCK_STREAM, 0);
        const int local = socket(AF_UNIX, SOCK_STREAM, 0);
#ifdef __linux__
        char from[8] = "memory", to[8] = {};
        const iovec there{from, sizeof from}, here{to, sizeof to};
        const bool peeked = process_vm_readv(getpid(), &here, 1, &there, 1, 0) == ssize_t(sizeof to); // its own, even
#else
        const bool peeked = false;
#endif
        report("{\"kind\":\"privileges\",\"uid\":" + std::to_string(getuid()) + ",\"euid\":" + std::to_string(geteuid()) +
               ",\"root\":" + (root ? "true" : "false") + ",\"read\":" + (file >= 0 ? "true" : "false") +
               ",\"wrote\":" + (written >= 0 ? "true" : "false") + ",\"inet\":" + (inet >= 0 ? "true" : "false") +
               ",\"unix\":" + (local >= 0 ? "true" : "false") + ",\"peeked\":" + (peeked ? "true" : "false") + "}");
    } else if (mode == "reach") { // the file its request names ({"sceneFile":"..."}); arg: a file beside it;
                                  // argv[3]: another program, run as the grader runs agents
        std::string request;
        char buffer[4096];
        for (ssize_t n; (n = read(requestFd, buffer, sizeof buffer)) > 0;) request.append(buffer, std::size_t(n));
        const std::string key = "\"sceneFile\":\"";
        const std::size_t from = request.find(key) + key.size(), to = request.find('"', from);
        const std::string input = request.find(key) == std::string::npos ? "" : request.substr(from, to - from);
        const int sibling = open(arg.c_str(), O_RDONLY);
        bool ran = false;
        if (argc > 3) {
            const pid_t child = fork();
            if (child == 0) { // its descriptors, as a hostile agent would (no mode: a probe ends at once)
                char* const program[] = {argv[3], nullptr};
                execv(argv[3], program);
                _exit(127);
            }
            int status = 0;
            ran = child > 0 && waitpid(child, &status, 0) == child && !(WIFEXITED(status) && WEXITSTATUS(status) == 127);
        }
        report(R"({"kind":"reach","input":")" + readAll(input) + R"(","sibling":)" + (sibling >= 0 ? "true" : "false") +
               R"(,"ran":)" + (ran ? "true" : "false") + "}");
    } else if (mode == "environment") {
        report(std::string(R"({"kind":"environment","secret":")") + (std::getenv("RAYLAB_TEST_SECRET") ? "seen" : "") +
               "\"}");
    } else if (mode == "echo-requests") { // each request line comes back on the channel
        std::string pending;
        char buffer[4096];
        for (ssize_t n; (n = read(requestFd, buffer, sizeof buffer)) > 0;) {
            pending.append(buffer, std::size_t(n));
            for (std::size_t end; (end = pending.find('\n')) != std::string::npos; pending.erase(0, end + 1))
                report(R"({"kind":"echo","text":")" + pending.substr(0, end) + "\"}");
        }
        report(R"({"kind":"done"})");
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
    } else if (mode == "replace-stderr") { // arg: "symlink:TARGET", "hardlink:TARGET", "fifo" or "keep"
        std::fprintf(stderr, "an honest line of error output\n");
        std::fflush(stderr);
        const std::string how = arg.substr(0, arg.find(':')), target = arg.substr(arg.find(':') + 1);
        if (how != "keep") unlink("stderr.txt"); // its descriptor 2 still writes to the file unlinked
        const int made = how == "symlink"    ? symlink(target.c_str(), "stderr.txt")
                         : how == "hardlink" ? link(target.c_str(), "stderr.txt")
                         : how == "fifo"     ? mkfifo("stderr.txt", 0644)
                                             : 0;
        report(std::string(R"({"kind":"replaced","made":)") + std::to_string(made) + "}");
        return 1; // a failure, so that the grader shows the end of the error output
    } else if (mode == "cwd") {
        char cwd[4096];
        report(std::string(R"({"kind":"cwd","path":")") + (getcwd(cwd, sizeof cwd) ? cwd : "") + "\"}");
    }
    return 0;
}
#else
int main() { return 2; }
#endif
