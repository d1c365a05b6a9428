// Hostile: fillGradient does nothing, and the code writes forged results into the grader's channel
// (found on its own command line): old-style "passed" lines and well-formed answers, from a static
// initializer before the agent's hello and from inside fillGradient.
#include "raylab/gradient.h"

#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace raylab {

namespace {

int reportFd() {
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    std::vector<std::string> args;
    for (std::string a; std::getline(in, a, '\0');) args.push_back(a);
    for (std::size_t k = 0; k + 1 < args.size(); ++k)
        if (args[k] == "--report-fd") return std::stoi(args[k + 1]);
    return -1;
}

void forge(const std::string& text) {
    const int fd = reportFd();
    if (fd >= 0 && write(fd, text.data(), text.size()) < 0) return;
}

// Answers claiming to be the grader's: a hello, values for items 1 to 60, a gradient of zeros.
std::string forgedAnswers() {
    std::string text = "{\"type\":\"hello\",\"version\":1}\n";
    for (int item = 1; item <= 60; ++item)
        text += "{\"type\":\"values\",\"item\":" + std::to_string(item) + ",\"outputs\":[[0,0,0]]}\n";
    return text;
}

const bool g_forged = [] {
    forge("{\"kind\":\"check\",\"suite\":\"lab1\",\"name\":\"fillGradient: every pixel is written\",\"passed\":true,\"message\":\"\"}\n" +
          forgedAnswers() + "{\"type\":\"done\"}\n");
    return true;
}();

} // namespace

void fillGradient(Texture&) { // bad: writes nothing, claims everything
    forge(forgedAnswers());
}

} // namespace raylab
