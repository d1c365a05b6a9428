#pragma once
// Text put inside HTML, XML or SVG (an element's content or a quoted attribute): the reports, the
// JUnit XML and the study's plots.

#include <string>

namespace raylab {

// `text` with & < > " ' written as entities, so that it reads as itself and never as markup.
std::string escapeMarkup(const std::string& text);

} // namespace raylab
