#include "report/pdf.h"

#include "grader/sandbox/process.h"

#include <cstdlib>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>

namespace raylab::report {

namespace fs = std::filesystem;

namespace {

// file:///C:/out/report.html on Windows, file:///home/... elsewhere.
std::string fileUrl(const fs::path& file) {
    const std::string path = fs::absolute(file).generic_string();
    return (path.front() == '/' ? "file://" : "file:///") + path;
}

bool isPdf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    char head[5] = {};
    in.read(head, 4);
    return std::string(head) == "%PDF";
}

} // namespace

std::optional<fs::path> findChromium() {
    for (const char* name :
         {"chromium", "chromium-browser", "google-chrome", "google-chrome-stable", "chrome", "msedge"})
        if (fs::path found = grader::findProgram(name); !found.empty()) return found;
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
         "--print-to-pdf=" + partial.string(), fileUrl(html)},
        {{}, grader::kNullDevice, 120.});
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
