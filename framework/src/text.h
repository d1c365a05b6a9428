#pragma once
// Numbers and vectors as error messages show them: shortest form, "(1, 2, 3)", "nan", "inf"; and
// text from outside (a folder's name, a compiler's or an agent's message) as a reader may see it.

#include <glm/vec3.hpp>

#include <filesystem>
#include <string>
#include <string_view>

namespace raylab {

std::string showNumber(double value);
std::string showVector(const glm::vec3& v);

enum class TextForm {
    Message, // line breaks and tabs kept
    Name,    // one line that tells any two byte strings apart: also \n, \t, \r and \\ escaped
};

// `text` as well-formed UTF-8 that no terminal, XML parser or spreadsheet misreads: each byte that
// is not part of a well-formed UTF-8 character, each control character (C0, DEL, C1), the
// non-characters U+FFFE and U+FFFF, and each character that shows as nothing or reorders the text
// around it (the bidi controls U+202A to U+202E and U+2066 to U+2069, LRM, RLM, ALM, the zero-width
// characters, every other format character and default-ignorable code point, U+2028 and U+2029)
// are written \xHH, byte by byte: U+202E is \xE2\x80\xAE. So two names that differ in their bytes
// never print alike, as they would with U+FFFD, and no name reverses the text after it.
std::string printableText(std::string_view text, TextForm form = TextForm::Message);

// A name (a student's folder, a file of a submission) as the console, grades.csv and the reports
// show it: printableText's Name form, so a newline or an escape sequence in it shows as \n or \x1B
// and never moves the cursor. Every name and path printed goes through it (or printablePath).
std::string printableName(std::string_view name);

// A path so, with '/' between its folders on every system (a '\' would show doubled).
std::string printablePath(const std::filesystem::path& path);

} // namespace raylab
