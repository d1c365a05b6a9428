#pragma once
// report.md is the student's document. It is a sequence of segments, each between markers:
//   <!-- raylab:generated KEY hash=H --> ... <!-- raylab:end -->   rewritten on every run
//   <!-- raylab:student KEY --> ... <!-- raylab:end -->            the student's, kept by KEY
// A re-run places each student segment by its KEY (never by position). Whatever it cannot place (text
// outside the markers, a KEY it no longer writes, an edited generated part) goes to the "kept" segment.

#include "report/words.h"

#include <string>
#include <vector>

namespace raylab::report {

struct Segment {
    enum class Kind { Generated, Student };
    Kind kind = Kind::Generated;
    std::string key;
    std::string text; // Markdown, ending with a newline (or empty)
};

// The key of the segment that holds what could not be placed.
inline constexpr const char* kKeptKey = "kept";

// A piece of the previous report.md that the new one cannot place, and where it was.
struct UnplacedText {
    enum class Origin {
        OutsideMarkers, // text outside any marker
        EditedGenerated, // an edit inside a generated part (`section`)
        SectionGone,    // the student's section `section`, which this run no longer writes
        SecondCopy,     // a second copy of the student's section `section`
    };
    Origin origin = Origin::OutsideMarkers;
    std::string section;
    int line = 0; // its first line in the previous report.md
    std::string text; // with its note, as the kept section shows it (empty for a student section)
};

struct PreviousText {
    std::vector<Segment> student;       // in the order found; a key may appear twice
    std::vector<int> studentLines;      // the line of each one's begin marker
    std::vector<UnplacedText> unplaced; // text outside any marker, and edited generated parts (with a note)
};

// Reads an earlier report.md (any text: markers may be missing, moved or deleted).
PreviousText readPreviousText(const std::string& markdown, const Words& words);

// `fresh`: this run's document, its student segments holding the placeholders. Each takes the
// previous text of its key; the rest goes, with a heading, into a kept segment at the end, and is
// listed in `moved` when given (what was in the kept segment already is not moved again).
std::vector<Segment> placeStudentText(std::vector<Segment> fresh, const PreviousText& previous, const Words& words,
                                      std::vector<UnplacedText>* moved = nullptr);

// What the console says of the text moved into the kept segment of `file`: where each piece was
// (its line and section), and where it is now; empty when nothing moved.
std::string movedTextNotice(const std::vector<UnplacedText>& moved, const std::string& file, const Words& words);

// The Markdown file, markers and all.
std::string toMarkdown(const std::vector<Segment>& document);

} // namespace raylab::report
