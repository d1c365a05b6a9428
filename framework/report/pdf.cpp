#include "report/pdf.h"

#include "grader/sandbox/process.h"

#include <cstdlib>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace raylab::report {

namespace fs = std::filesystem;

namespace {

bool isPdf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    char head[5] = {};
    in.read(head, 4);
    return std::string(head) == "%PDF";
}

} // namespace

std::optional<fs::path> findChromium() {
    const char* path = std::getenv("PATH");
    std::string folders = path ? path : "/usr/bin:/bin";
    for (std::size_t begin = 0, end = 0; begin <= folders.size(); begin = end + 1) {
        end = folders.find(':', begin);
        if (end == std::string::npos) end = folders.size();
        for (const char* name : {"chromium", "chromium-browser", "google-chrome", "google-chrome-stable"}) {
            const fs::path candidate = fs::path(folders.substr(begin, end - begin)) / name;
            std::error_code e;
            if (fs::is_regular_file(candidate, e) && access(candidate.c_str(), X_OK) == 0) return candidate;
        }
    }
    return std::nullopt;
}

void printToPdf(const fs::path& chromium, const fs::path& html, const fs::path& pdf, const Words& words) {
    std::random_device random;
    const fs::path profile = fs::temp_directory_path() / ("raylab-chromium-" + std::to_string(random()));
    const fs::path partial = pdf.string() + ".partial";
    fs::remove(partial);
    // Its output to the null device; a browser that hangs is stopped after two minutes.
    const grader::ProcessResult printed = grader::runProcess(
        {chromium.string(), "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--no-first-run", "--user-data-dir=" + profile.string(), "--no-pdf-header-footer",
         "--print-to-pdf=" + partial.string(), "file://" + fs::absolute(html).string()},
        {{}, "/dev/null", 120.});
    std::error_code ignored;
    fs::remove_all(profile, ignored);
    if (!printed.started) throw std::runtime_error(printed.error);
    const int status = printed.signal != 0 ? 128 + printed.signal : printed.exitCode;
    if (status != 0 || !isPdf(partial)) {
        fs::remove(partial, ignored);
        throw std::runtime_error(words.text("pdf_failed", {{"program", chromium.string()}, {"file", html.string()},
                                                           {"status", std::to_string(status)}}));
    }
    fs::rename(partial, pdf); // whole or nothing
}

} // namespace raylab::report
