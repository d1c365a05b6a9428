#pragma once
// The files tests read back and the scratch folders they write in.

#include <filesystem>
#include <fstream>
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

// The empty folder `name` in the system's temporary folder (emptied when it exists).
inline std::filesystem::path freshFolder(const std::string& name) {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

} // namespace raylab::test
