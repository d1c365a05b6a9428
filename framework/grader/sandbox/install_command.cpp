#include "grader/sandbox/install_command.h"

#include "grader/sandbox/process.h"

#ifndef _WIN32
#include <unistd.h>
#endif

namespace raylab::grader {

std::string installCommand(const std::string& debian, const std::string& homebrew, const std::string& windows) {
#if defined(_WIN32)
    (void)debian, (void)homebrew;
    return windows;
#elif defined(__APPLE__)
    (void)debian, (void)windows;
    return "brew install " + homebrew;
#else
    (void)homebrew, (void)windows;
    const std::string apt = "apt-get install -y " + debian;
    if (geteuid() == 0) return apt;
    if (!findProgram("sudo").empty()) return "sudo " + apt;
    return "su root -c '" + apt + "'";
#endif
}

} // namespace raylab::grader
