// Bubblewrap: whether it can make its namespaces here, and its arguments for an agent.
#include "grader/sandbox/sandbox_internal.h"

#ifdef RAYLAB_POSIX_SANDBOX

#include "grader/sandbox/process.h"

#include <iterator>

namespace raylab::grader::detail {

namespace fs = std::filesystem;

namespace {

// The namespaces and limits of every bubblewrap run (the probe below tries them all).
const char* const kBubblewrapIsolation[] = {"--unshare-pid", "--unshare-net", "--unshare-ipc", "--unshare-uts",
                                            "--unshare-cgroup-try", "--die-with-parent", "--new-session",
                                            "--cap-drop", "ALL"};

void addBind(std::vector<std::string>& args, const char* how, const fs::path& path) {
    args.insert(args.end(), {how, path.string(), path.string()});
}

} // namespace

const BubblewrapProbe& bubblewrapProbe() {
    static const BubblewrapProbe found = [] {
        BubblewrapProbe probe;
#ifdef __linux__
        probe.program = findProgram("bwrap");
        if (probe.program.empty()) return probe;
        std::vector<std::string> argv{probe.program.string()};
        argv.insert(argv.end(), std::begin(kBubblewrapIsolation), std::end(kBubblewrapIsolation));
        argv.insert(argv.end(), {"--ro-bind", "/", "/", "--", "/bin/true"});
        probe.works = runProcess(argv, {{}, "/dev/null"}).succeeded();
#endif
        return probe;
    }();
    return found;
}

fs::path bubblewrap() {
    const BubblewrapProbe& probe = bubblewrapProbe();
    return probe.works ? probe.program : fs::path();
}

std::vector<std::string> bubblewrapSystem(const fs::path& bwrap, const fs::path& tmp) {
    std::vector<std::string> args{bwrap.string()};
    args.insert(args.end(), std::begin(kBubblewrapIsolation), std::end(kBubblewrapIsolation));
    args.insert(args.end(), {"--ro-bind", "/usr", "/usr", "--dev", "/dev"});
    if (tmp.empty()) args.insert(args.end(), {"--tmpfs", "/tmp"});
    else args.insert(args.end(), {"--bind", tmp.string(), "/tmp"});
    // /lib, /bin ... are links into /usr on merged systems, folders elsewhere.
    for (const char* top : kSystemTopFolders) {
        std::error_code error;
        if (fs::is_symlink(top, error)) args.insert(args.end(), {"--symlink", fs::read_symlink(top).string(), top});
        else if (fs::is_directory(top, error)) addBind(args, "--ro-bind", top);
    }
    for (const char* file : kSystemEtcFiles) addBind(args, "--ro-bind-try", file);
    return args;
}

fs::path agentTmp(const fs::path& scratch) { return scratch / "tmp"; }

std::vector<std::string> bubblewrapArgs(const fs::path& bwrap, const AgentCommand& c) {
    std::vector<std::string> args = bubblewrapSystem(bwrap, agentTmp(c.scratch));
    args.insert(args.end(), {"--proc", "/proc"});
    addBind(args, "--bind", c.scratch);
    for (const fs::path& folder : c.writable) addBind(args, "--bind", folder);
    for (const fs::path& input : c.readable) addBind(args, "--ro-bind-try", input);
    addBind(args, "--ro-bind", c.program);
    args.insert(args.end(), {"--chdir", c.scratch.string(), "--"});
    return args;
}

} // namespace raylab::grader::detail

#endif
