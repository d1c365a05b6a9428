#pragma once
// The document the watch page shows (PageState publishes it): the last grade's figures, checks and
// labs, and what the watch is doing. While the latest save does not compile, the grade is the last
// build's that compiled: the document says it is stale ("stale": true, on itself and on each figure
// and check), beside the compiler's errors, until a build compiles again.

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::watch {

struct PageFacts {
    int lab = 0;
    std::string phase;                 // building, build_failed, grading, ready
    std::vector<std::string> changed;  // the saved files, relative to the tree
    std::string buildOutput;           // the last build's output when it failed; empty when it compiled
    std::filesystem::path sourceDir;   // the tree (the errors' files are named relative to it)
    double buildSeconds = 0., gradeSeconds = 0.;
};

// `graded`: the last grade, as JSON members ("figures", "checks", "labs", "problems"); the document,
// as JSON text, in the reader's language.
std::string pageDocument(const std::string& graded, const PageFacts& facts);

// JSON text that never throws: every name and message is made printable before it goes in (so it is
// UTF-8); a byte that slipped through would become U+FFFD, not an exception that ends the watch.
std::string jsonText(const nlohmann::json& value);

} // namespace raylab::watch
