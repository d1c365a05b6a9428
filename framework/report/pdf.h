#pragma once
// raylab report --pdf: the HTML printed by a headless chromium, when one is installed.

#include "words.h"

#include <filesystem>
#include <optional>

namespace raylab::report {

// chromium (or chromium-browser, google-chrome; chrome or msedge on Windows) on the PATH; none when there is none.
std::optional<std::filesystem::path> findChromium();

// Prints `html` to `pdf`; throws std::runtime_error when chromium fails or writes no PDF.
void printToPdf(const std::filesystem::path& chromium, const std::filesystem::path& html, const std::filesystem::path& pdf,
                const Words& words);

} // namespace raylab::report
