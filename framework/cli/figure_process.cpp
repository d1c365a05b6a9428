// raylab figures, lab and render draw each figure in a child process (POSIX), so that a lab function
// that crashes costs that figure only: the command goes on with the others and ends with an error
// status, never a signal. When a figure's child crashed, a second child calls the figure's lab
// functions one at a time on the figure's own rays (the steps the labs register, src/figure_steps.h)
// and reports the one it was in when it crashed.
// Elsewhere (Windows) a figure is drawn in the command's own process.
#include "figure_process.h"

#include "src/figure_steps.h"
#include "src/messages.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#if defined(__unix__) || defined(__APPLE__)
#include <csignal>
#include <sys/wait.h>
#include <unistd.h>
#define RAYLAB_FIGURE_CHILD 1
#endif

namespace raylab::cli {

#ifndef RAYLAB_FIGURE_CHILD

FigureResult renderFigure(const SceneDescription& description, const RenderOptions& options, const grader::LabCatalog&) {
    return renderScene(description, options);
}

#else

namespace {

// ---- what a child sends back: a FigureResult, field by field, through a pipe ----------------

void writeAll(int fd, const void* data, std::size_t size) {
    const char* bytes = static_cast<const char*>(data);
    while (size > 0) {
        const ssize_t n = write(fd, bytes, size);
        if (n <= 0) _exit(2); // the parent is gone
        bytes += n;
        size -= std::size_t(n);
    }
}

template <class T> void put(int fd, const T& value) { writeAll(fd, &value, sizeof value); }
void putString(int fd, const std::string& text) {
    put(fd, std::uint64_t(text.size()));
    writeAll(fd, text.data(), text.size());
}

void sendResult(int fd, const FigureResult& r) {
    put(fd, int(r.status));
    putString(fd, r.message);
    put(fd, r.todo.has_value());
    if (r.todo) {
        putString(fd, r.todo->lab());
        putString(fd, r.todo->function());
        putString(fd, r.todo->file());
        put(fd, r.todo->line());
    }
    put(fd, r.stats);
    put(fd, r.image.has_value());
    if (r.image) {
        put(fd, r.image->width());
        put(fd, r.image->height());
        writeAll(fd, r.image->pixels().data(), r.image->pixels().size() * sizeof(Color));
    }
}

// Reads what sendResult wrote; throws std::runtime_error when the bytes end early (a crash).
class Reader {
public:
    explicit Reader(std::string bytes) : m_bytes(std::move(bytes)) {}
    void read(void* out, std::size_t size) {
        if (m_bytes.size() - m_at < size) throw std::runtime_error("cut short");
        std::memcpy(out, m_bytes.data() + m_at, size);
        m_at += size;
    }
    template <class T> T get() {
        T value;
        read(&value, sizeof value);
        return value;
    }
    std::string getString() {
        const auto size = get<std::uint64_t>();
        if (m_bytes.size() - m_at < size) throw std::runtime_error("cut short");
        std::string text = m_bytes.substr(m_at, size);
        m_at += size;
        return text;
    }

private:
    std::string m_bytes;
    std::size_t m_at = 0;
};

FigureResult receiveResult(Reader in) {
    FigureResult r;
    r.status = FigureResult::Status(in.get<int>());
    r.message = in.getString();
    if (in.get<bool>()) {
        std::string lab = in.getString(), function = in.getString(), file = in.getString();
        r.todo = NotDoneYet(std::move(lab), std::move(function), std::move(file), in.get<int>());
    }
    r.stats = in.get<RenderStats>();
    if (in.get<bool>()) {
        const int width = in.get<int>(), height = in.get<int>();
        Texture image(width, height);
        std::vector<Color> pixels(std::size_t(width) * std::size_t(height));
        in.read(pixels.data(), pixels.size() * sizeof(Color));
        for (int j = 0; j < height; ++j)
            for (int i = 0; i < width; ++i) image.setPixel(i, j, pixels[std::size_t(j) * std::size_t(width) + std::size_t(i)]);
        r.image = std::move(image);
    }
    return r;
}

// ---- the child ------------------------------------------------------------------------------

struct Child {
    std::string output; // all it wrote on its pipe
    int signal = 0;     // the signal that ended it, if one did
};

// Runs `work(fd)` in a child process and collects what it writes on fd until it ends.
template <class Work> Child runChild(const Work& work) {
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    std::fflush(stdout);
    std::fflush(stderr);
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
    if (pid == 0) {
        close(fds[0]);
        work(fds[1]);
        std::fflush(stdout);
        _exit(0);
    }
    close(fds[1]);
    Child child;
    char buffer[1 << 16];
    for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) != 0;) {
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) break;
        child.output.append(buffer, std::size_t(n));
    }
    close(fds[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    if (WIFSIGNALED(status)) child.signal = WTERMSIG(status);
    return child;
}

// ---- finding the function that crashed ----------------------------------------------------

// The lab function the finder is in, written by the crash handler (set before each call).
const char* volatile g_inFunction = nullptr;
int g_crashFd = -1;

extern "C" void onCrash(int signal) {
    if (const char* name = g_inFunction) writeAll(g_crashFd, name, std::strlen(name));
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

// Calls the figure's lab functions one at a time, as the labs' grading folders registered them
// (src/figure_steps.h), on its pixel centres' rays: the function it crashes in is the first one
// whose own call crashed.
void callOneAtATime(const SceneDescription& d, const RenderOptions& options, const grader::LabCatalog& labs, int fd) {
    g_crashFd = fd;
    for (int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(signal, onCrash);
    std::vector<const grader::LabDescription*> inOrder; // a given lab's steps in its place (its camera makes the rays)
    for (const auto* list : {&labs.labs, &labs.given})
        for (const grader::LabDescription& lab : *list) inOrder.push_back(&lab);
    std::sort(inOrder.begin(), inOrder.end(), [](const auto* a, const auto* b) { return a->number < b->number; });
    std::vector<std::string> order;
    for (const grader::LabDescription* lab : inOrder) order.push_back(lab->id);
    try {
        runFigureSteps(d, options, order, [](const std::string& function) { g_inFunction = function.c_str(); });
    } catch (...) { // a stub or an error: not a crash, and the figure's own result says it
    }
    g_inFunction = nullptr;
}

std::string signalName(int signal) {
    switch (signal) {
    case SIGSEGV: return tr("sandbox.segfault");
    case SIGABRT: return tr("sandbox.aborted");
    default: return tr("sandbox.signal", {{"signal", std::to_string(signal)}});
    }
}

} // namespace

FigureResult renderFigure(const SceneDescription& d, const RenderOptions& options, const grader::LabCatalog& labs) {
    const Child child = runChild([&](int fd) { sendResult(fd, renderScene(d, options)); });
    if (child.signal == 0) try {
            return receiveResult(Reader(child.output));
        } catch (const std::runtime_error&) { // cut short without a signal: it exited on its own
        }
    FigureResult crashed;
    crashed.status = FigureResult::Status::Failed;
    const std::string function = runChild([&](int fd) { callOneAtATime(d, options, labs, fd); }).output;
    const grader::LabDescription* lab = nullptr;
    for (const grader::LabDescription& l : labs.labs)
        for (const grader::LabFunction& f : l.functions)
            if (f.name == function) lab = &l;
    crashed.message = lab != nullptr ? tr("figures.crashed_in", {{"how", signalName(child.signal)},
                                                                   {"lab", std::to_string(lab->number)},
                                                                   {"function", titleInLanguage(function)},
                                                                   {"folder", "labs/" + lab->id + "/"}})
                                     : tr("figures.crashed", {{"how", child.signal != 0 ? signalName(child.signal) : tr("sandbox.exited")}});
    return crashed;
}

#endif

} // namespace raylab::cli
