#pragma once
// The report's title block, from report.toml: the student fills it once (the first run creates it
// with placeholders).

#include "report/words.h"

#include <filesystem>
#include <string>

namespace raylab::report {

struct TitleBlock {
    std::string name, group, course, date;
    bool placeholders = false; // report.toml was just created, or still holds its placeholders
};

// Reads `file`, creating it first (in the words' language) when it does not exist. Throws
// std::runtime_error "FILE:LINE: key: problem" for a file it cannot use.
TitleBlock readTitleBlock(const std::filesystem::path& file, const Words& words);

} // namespace raylab::report
