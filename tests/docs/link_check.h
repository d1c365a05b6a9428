#pragma once
// Finds the relative links and images of Markdown files that do not resolve to a file of the tree.

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::test {

struct BrokenLink {
    std::filesystem::path file; // the Markdown file, relative to the root
    int line = 0;
    std::string target;         // as written
    std::filesystem::path resolved; // relative to the root
};

// The Markdown files under `root`, skipping .git, build trees and out/.
std::vector<std::filesystem::path> markdownFiles(const std::filesystem::path& root);

// The links of one Markdown file (inline links and images, reference definitions, HTML src and href)
// outside code blocks and code spans, that are neither URLs nor in-page anchors, and whose file
// does not exist.
std::vector<BrokenLink> brokenLinks(const std::filesystem::path& root, const std::filesystem::path& markdown);

// How many relative links `brokenLinks` looked at in all (so that a test can tell it saw some).
extern int g_linksChecked;

} // namespace raylab::test
