#pragma once
// The grader's words a student may not know (LSB, RMSE, NaN) are explained in the glossary of the
// handouts' language (docs/glossary.md, docs/glossaire.md): the first line that uses one points there.

#include <string>
#include <utility>
#include <vector>

namespace raylab::grader {

// Each term the console may print and its anchor in both glossaries.
const std::vector<std::pair<std::string, std::string>>& glossaryTerms();

// `text` with " (see docs/glossary.md#lsb)" after the first line holding each term as a word, in the
// reader's language; a line holding several new terms links them all at once.
std::string withGlossaryLinks(const std::string& text);

} // namespace raylab::grader
