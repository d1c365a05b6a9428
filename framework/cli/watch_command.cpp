// raylab watch [N]: a live page of lab N's pictures beside the references, their difference and the
// lab's checks, rebuilt and graded again at every save of a lab file (framework/watch/ does the work).
#include "build_info.h"
#include "commands.h"

#include "grader/lab_catalog.h"
#include "grader/sandbox/process.h"
#include "src/atomic_file.h"
#include "src/messages.h"
#include "src/text.h"
#include "watch/file_watcher.h"
#include "watch/http_rules.h"
#include "watch/pixel_inspector.h"
#include "watch/watch_server.h"
#include "watch/watch_session.h"

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace raylab::cli {

namespace {

namespace fs = std::filesystem;

struct WatchOptions {
    int lab = 0; // 0: the latest lab with code
    int port = 0;
    std::string out = "out/watch";
    bool noOpen = false;
};

volatile std::sig_atomic_t g_stop = 0;
extern "C" void onWatchStop(int) { g_stop = 1; }

// How many stubs (RAYLAB_TODO) the lab's files still hold.
int stubsLeft(const grader::LabDescription& lab) {
    int count = 0;
    for (const std::string& file : lab.files()) {
        std::ifstream in(labsFolder() / lab.id / file);
        const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        for (std::size_t at = text.find("RAYLAB_TODO("); at != std::string::npos; at = text.find("RAYLAB_TODO(", at + 1)) ++count;
    }
    return count;
}

// The latest lab of which a function is written (fewer stubs than functions); lab 1 when none is.
int latestLabWithCode(const grader::LabCatalog& labs) {
    int latest = labs.labs.empty() ? 1 : labs.labs.front().number;
    for (const grader::LabDescription& lab : labs.labs)
        if (stubsLeft(lab) < int(lab.functions.size())) latest = lab.number;
    return latest;
}

// The file the browser is given, which leads it to the page: never the page's address, whose token any
// user of the machine would read on the browser's command line (ps) and then open the page with. The
// file is in a folder its owner alone may enter; nothing when that cannot be made so.
std::optional<fs::path> browserLauncher(const fs::path& out, const std::string& address) {
    const fs::path folder = out / "browser";
    std::error_code error;
    fs::create_directories(folder, error);
    fs::permissions(folder, fs::perms::owner_all, fs::perm_options::replace, error);
#ifndef _WIN32 // Windows: the folder's access is the user profile's, inherited
    if (error || (fs::status(folder, error).permissions() & (fs::perms::group_all | fs::perms::others_all)) != fs::perms::none)
        return std::nullopt;
#endif
    const fs::path page = folder / "open.html";
    writeFileAtomically(page, "<!doctype html>\n<meta charset=\"utf-8\">\n<meta http-equiv=\"refresh\" content=\"0; url=" + address +
                                  "\">\n<title>raylab watch</title>\n<a href=\"" + address + "\">raylab watch</a>\n");
    return page;
}

// Opens the page in the desktop's browser where there is one; nothing where there is not (a server, CI).
void openInBrowser(const fs::path& out, const std::string& address) {
#if defined(_WIN32)
    const fs::path opener = grader::findProgram("explorer");
#elif defined(__APPLE__)
    const fs::path opener = grader::findProgram("open");
#else
    const bool desktop = std::getenv("DISPLAY") != nullptr || std::getenv("WAYLAND_DISPLAY") != nullptr;
    const fs::path opener = desktop ? grader::findProgram("xdg-open") : fs::path();
#endif
    if (opener.empty()) return;
    try {
        const std::optional<fs::path> launcher = browserLauncher(out, address);
        if (launcher) grader::runProcess({opener.string(), launcher->string()}, {.output = grader::kNullDevice});
    } catch (const std::exception&) { // the address is printed: the student opens it
    }
}

int runWatch(const WatchOptions& o, const Context& context) {
    const grader::LabCatalog labs = courseLabs();
    const int lab = o.lab != 0 ? o.lab : latestLabWithCode(labs);
    const grader::LabDescription* watched = labs.lab(lab);
    if (watched == nullptr)
        throw std::invalid_argument(tr("figures.no_such_lab", {{"lab", std::to_string(lab)}, {"labs", labList(labs)}}));
    watch::WatchSettings settings{lab,
                                  fs::absolute(o.out),
                                  build::kSourceDir,
                                  build::kBuildDir,
                                  build::kBinaryDir,
                                  RAYLAB_CMAKE_COMMAND,
                                  build::kBuildType,
                                  referenceFolders(""),
                                  labsFolder(),
                                  context.scenes,
                                  context.threads};
    fs::create_directories(settings.out);
    watch::PageState page;
    std::mutex agents;
    watch::WatchSession session(settings, page, agents);
    const watch::PixelInspector inspector(session.settings(), labs, agents);
    watch::WatchServer server(page, settings.out, watch::newToken(),
                              [&inspector](const std::string& figure, int x, int y) { return inspector.inspect(figure, x, y); });
    server.bind(o.port);
    // The server's thread is stopped and joined on every way out, an exception's too: a joinable
    // thread left behind would end the program (std::terminate) instead of saying what went wrong.
    std::thread serving([&server] { server.serve(); });
    const struct StopServing {
        watch::WatchServer& server;
        std::thread& serving;
        ~StopServing() {
            server.stop();
            serving.join();
        }
    } stopServing{server, serving};
    watch::FileWatcher files({labsFolder() / watched->id});
    // Ctrl-C stops it cleanly from the moment the address is printed (the browser may open at once).
    std::signal(SIGINT, onWatchStop);
    std::signal(SIGTERM, onWatchStop);
    std::printf("%s\n", tr("watch.serving", {{"lab", std::to_string(lab)}, {"address", server.address()},
                                             {"folder", "labs/" + watched->id + "/"}, {"how", files.how()}})
                            .c_str());
    std::fflush(stdout);
    if (!o.noOpen) openInBrowser(settings.out, server.address());

    std::vector<fs::path> changed;
    bool first = true;
    while (g_stop == 0) {
        if (first || !changed.empty()) {
            // Whatever a save brings (a file name of any bytes, a compiler's output of any kind), the
            // page keeps serving: a problem is said, and the next save tries again.
            try {
                if (!first) std::printf("%s\n", tr("watch.saved", {{"file", printablePath(fs::relative(changed.front(), build::kSourceDir))}}).c_str());
                std::fflush(stdout);
                session.refresh(changed);
                std::printf("%s\n", tr("watch.refreshed", {{"address", server.address()}}).c_str());
            } catch (const std::exception& e) {
                std::printf("%s\n", tr("watch.problem", {{"problem", printableText(e.what())}}).c_str());
                try {
                    session.showProblem(e.what());
                } catch (const std::exception&) { // said in the console already
                }
            }
            std::fflush(stdout);
            first = false;
        }
        // Saves made during a build are waiting here: one build at a time, none lost.
        changed = files.changes(std::chrono::milliseconds(200));
        if (!changed.empty()) { // an editor's save is often several writes: take them all
            for (auto more = files.changes(std::chrono::milliseconds(50)); !more.empty(); more = files.changes(std::chrono::milliseconds(50)))
                changed.insert(changed.end(), more.begin(), more.end());
        }
    }
    std::printf("%s\n", tr("watch.stopped").c_str());
    return 0;
}

} // namespace

void addWatchCommand(CLI::App& app, Context& context) {
    auto options = std::make_shared<WatchOptions>();
    CLI::App* watch = app.add_subcommand("watch", tr("cli.watch"));
    watch->add_option("N", options->lab, tr("cli.watch_lab"))->check(CLI::PositiveNumber);
    watch->add_option("--port", options->port, tr("cli.watch_port"))->check(integerIn(1, 65535));
    watch->add_option("--out", options->out, tr("cli.watch_out"));
    watch->add_flag("--no-open", options->noOpen, tr("cli.watch_no_open"));
    context.addRenderOptions(watch);
    watch->callback([&context, options] { context.exitStatus = runWatch(*options, context); });
}

} // namespace raylab::cli
