#pragma once
// The files tests read back and the scratch folders they write in.

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

namespace raylab::test {

// A file's bytes as they are ("" when it cannot be read).
inline std::string readFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// `name` in the system's temporary folder, made this build tree's own: ctest runs each test in its
// build folder, so two trees (two clones, two worktrees) testing at once never share a scratch folder,
// and a run finds and clears what the previous run of the same tree left.
inline std::filesystem::path scratchPath(const std::string& name) {
    const std::size_t tree = std::hash<std::string>{}(std::filesystem::current_path().string());
    const std::filesystem::path given(name);
    return std::filesystem::temp_directory_path() /
           (given.stem().string() + "-" + std::to_string(tree % 1000000007) + given.extension().string());
}

// The empty folder `name` in the system's temporary folder (emptied when it exists), this tree's own.
inline std::filesystem::path freshFolder(const std::string& name) {
    const std::filesystem::path folder = scratchPath(name);
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

} // namespace raylab::test
