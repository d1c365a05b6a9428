#include "build_info.h"
#include "commands.h"

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>
#ifdef _WIN32
#include <process.h>
#else
#include <unistd.h>
#endif

namespace raylab::cli {

int runOtherImpl(const std::string& impl, int argc, char** argv) {
    namespace fs = std::filesystem;
    const std::string name = impl == "reference" ? "raylab-reference" : "raylab";
    fs::path program = fs::path(build::kBinaryDir) / name;
#ifdef _WIN32
    program += ".exe";
#endif
    std::error_code error;
    if (!fs::exists(program, error)) {
        std::fprintf(stderr, "raylab: error: there is no %s build here (%s not found)%s\n", impl.c_str(),
                     program.string().c_str(),
                     impl == "reference" ? "; the reference build needs the solutions/ folder" : "");
        return 1;
    }
    std::vector<std::string> args{program.string()};
    for (int k = 1; k < argc; ++k) args.emplace_back(argv[k]);
    std::vector<char*> cargs;
    for (std::string& a : args) cargs.push_back(a.data());
    cargs.push_back(nullptr);
    std::fflush(stdout);
#ifdef _WIN32
    const auto status = _spawnv(_P_WAIT, program.string().c_str(), cargs.data());
    return status < 0 ? 1 : int(status);
#else
    execv(program.c_str(), cargs.data());
    std::perror(("raylab: cannot run " + program.string()).c_str());
    return 1;
#endif
}

} // namespace raylab::cli
