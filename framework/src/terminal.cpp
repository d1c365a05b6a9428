#include "src/terminal.h"

#include <cstdio>
#include <cstdlib>
#ifdef _WIN32
#include <io.h>
#define RAYLAB_ISATTY _isatty
#define RAYLAB_FILENO _fileno
#else
#include <unistd.h>
#define RAYLAB_ISATTY isatty
#define RAYLAB_FILENO fileno
#endif

namespace raylab {

bool stderrIsInteractive() {
    const char* ci = std::getenv("CI");
    if (ci != nullptr && *ci != '\0') return false;
    return RAYLAB_ISATTY(RAYLAB_FILENO(stderr)) != 0;
}

ProgressBar::ProgressBar(std::size_t total)
    : m_total(total), m_enabled(stderrIsInteractive()), m_start(std::chrono::steady_clock::now()) {}

void ProgressBar::update(std::size_t done) {
    if (!m_enabled || m_total == 0) return;
    if (!m_shown && std::chrono::steady_clock::now() - m_start < std::chrono::seconds(1)) return;
    m_shown = true;
    constexpr int kWidth = 40;
    const int filled = int(kWidth * done / m_total);
    std::fprintf(stderr, "\r  [%.*s%*s] %3d%%", filled, "########################################", kWidth - filled, "",
                 int(100 * done / m_total));
    std::fflush(stderr);
}

void ProgressBar::finish() {
    if (!m_shown) return;
    update(m_total);
    std::fputs("\r\033[K", stderr); // clear the line: the caller prints the result
    std::fflush(stderr);
}

} // namespace raylab
