#pragma once
// The course's list of the labs it hands out: course.toml at the top of the tree, `labs = [1, 2, 3]`
// (CMake reads the same line, cmake/RaylabLabs.cmake). The lab catalogue keeps these labs only.

#include <filesystem>
#include <optional>
#include <vector>

namespace raylab::grader {

// The course file of the tree whose labs are in `labs` (its course.toml, beside labs/).
std::filesystem::path courseFile(const std::filesystem::path& labs);

// The lab numbers the file lists, in its order, each one of `found`; nullopt when there is no such
// file (every lab found is the course's). Throws std::runtime_error "FILE:LINE: labs: problem".
std::optional<std::vector<int>> loadCourseList(const std::filesystem::path& file, const std::vector<int>& found);

} // namespace raylab::grader
