#pragma once
// A test of one lab (its figures, its mistakes) in a course that does not hand that lab out (course.toml:
// the lab is absent, or given) is skipped, never failed: it prints "skipped: lab N is not in this course
// (course.toml)", which its ctest entry reads (SKIP_REGULAR_EXPRESSION, RAYLAB_SKIPPED_LAB in
// tests/CMakeLists.txt). Such a test is a doctest suite of its own, so that the skip hides no other case.
#include "grader/lab_catalog.h"

#include <doctest/doctest.h>

#include <filesystem>

namespace raylab::test {

// Whether the course of the tree's labs/ hands out lab `number`; false, having printed the skip line, where not.
inline bool labInCourse(const std::filesystem::path& labs, int number) {
    if (grader::loadLabCatalog(labs).lab(number)) return true;
    MESSAGE("skipped: lab " << number << " is not in this course (course.toml)");
    return false;
}

} // namespace raylab::test
