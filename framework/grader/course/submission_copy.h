#pragma once
// Room course/: submissions, class runs, the autograders and the grade reports; it may include every other room.
//
// The grader's own copy of a submission, the only thing CMake and the compiler are given. The parent
// finds the lab files where students put them (lab folders, a labs/ folder, the whole repository,
// folders named otherwise such as tp3/ or "Lab 3/", or the files flat), by the names the labs'
// lab.toml declare, and copies regular files only: a link, a device, a pipe or a hard link could be
// the grader's own files, a classmate's or the solutions, or block the grader, so none is followed or
// read. The copy holds <lab id>/<declared name> and nothing else: whatever a file was called, CMake
// never sees a name the grader did not choose.

#include "grader/judge/grade.h"
#include "grader/lab_catalog.h"

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::grader {

struct SubmissionCopy {
    std::filesystem::path folder;     // <lab id>/<file> for every lab file found
    std::vector<int> labs;            // the labs at least one file of which was copied, in order
    std::vector<std::string> ignored; // "<path in the submission>: <why>", for what was not copied
};

// Copies the lab files of `submission` into `destination` (emptied first). Never throws for what the
// submission holds: what cannot be used is listed in `ignored`; throws raylab::WriteError when the
// copy cannot be written.
SubmissionCopy copySubmission(const std::filesystem::path& submission, const LabCatalog& catalog,
                              const std::filesystem::path& destination);

// "no lab file found: upload ...", naming the files and their folders, in the reader's language.
std::string noLabFileMessage(const LabCatalog& catalog);

// The grade's note on what was not graded (a heading, then a line each); empty when nothing was ignored.
std::string ignoredFilesNote(const SubmissionCopy& copy, const LabCatalog& catalog);

// A submission without any lab file: every item at zero, saying so (never "does not build").
GradeResult gradeWithoutLabFiles(const GradeSetup& setup, const SubmissionCopy& copy);

} // namespace raylab::grader
