#pragma once
// CSV as spreadsheets and RFC 4180 read it, whichever separator the spreadsheet splits at (',', or
// ';' as French Excel and LibreOffice asked for it do, or a tab): a cell holding a comma, a
// semicolon, a tab, a quote or a line break is quoted, its quotes doubled. A cell a spreadsheet would
// run as a formula (it starts with = + - @, a tab or a carriage return, and is not a plain number)
// is written with a leading ' (OWASP's advice against CSV injection), so a student named
// "=HYPERLINK(...)" reads as text; and so is each part of a cell after a separator or a line break
// (one ' before the = of "x;=1+1"), for a reader that splits there all the same.

#include <string>
#include <vector>

namespace raylab {

// One line of cells, ending with "\n".
std::string csvLine(const std::vector<std::string>& cells);

// The rows of a CSV text (a roster): quoted cells may hold commas, doubled quotes and line breaks;
// lines end with LF or CRLF; a UTF-8 byte order mark (as spreadsheets write it) is skipped. Throws
// std::runtime_error at a quote left open, naming its line.
std::vector<std::vector<std::string>> csvRows(const std::string& text);

} // namespace raylab
