#pragma once
// The command that installs a missing program on this machine, for the messages that ask for one: the
// same as scripts/setup.sh and cmake/RaylabInstallCommand.cmake say.
#include <string>

namespace raylab::grader {

// Linux: `apt-get install -y DEBIAN`, prefixed with sudo unless this process is root (a bare system or a
// container has no sudo), with `su root -c '...'` where there is no sudo; macOS: `brew install
// HOMEBREW`; Windows: WINDOWS (a winget command, or what to install).
std::string installCommand(const std::string& debian, const std::string& homebrew, const std::string& windows);

} // namespace raylab::grader
