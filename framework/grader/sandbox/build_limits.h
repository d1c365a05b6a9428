#pragma once
// The sizes a submission's build may reach: raylab-build-guard holds the compiler to the first
// (build_guard.cpp), the grader refuses programs past the second (course/submission.cpp), and both
// are named in the report. Nothing a student writes may fill the disk a class is graded on.

#include <cstdint>

namespace raylab::grader {

// The largest file the compiler of a lab file may write (its object, the assembly before it; its file
// size limit): the references' largest lab object is 69 KB (lab 5's pixel_samples.cpp, GCC 12 -O3)
// and its assembly 190 KB, so 32 MB is a margin of more than 150; a table or an `.incbin` of a
// gigabyte stops here.
inline constexpr std::uint64_t kCompilerFileBytes = std::uint64_t(32) << 20;

// The largest agent program: the references' are 1.4 MB (the framework, the grader and five labs),
// so 64 MB is a margin of more than 40 (the lab files' objects, each within kCompilerFileBytes, could
// still add up to more).
inline constexpr std::uint64_t kAgentProgramBytes = std::uint64_t(64) << 20;

} // namespace raylab::grader
