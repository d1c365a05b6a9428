#include "src/text.h"

#include <cstdio>
#include <sstream>

namespace raylab {

std::string showNumber(double value) {
    std::ostringstream out;
    out.precision(9); // enough to tell any two floats apart
    out << value;
    return out.str();
}

std::string showVector(const glm::vec3& v) {
    std::ostringstream out;
    out.precision(9);
    out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return out.str();
}

namespace {

// The length of the well-formed UTF-8 character at `at` (Unicode's table 3-7: no overlong form, no
// surrogate, nothing past U+10FFFF), or 0.
std::size_t characterLength(std::string_view text, std::size_t at) {
    const auto byte = [&](std::size_t k) { return at + k < text.size() ? static_cast<unsigned char>(text[at + k]) : 0u; };
    const auto tail = [&](std::size_t k, unsigned low = 0x80, unsigned high = 0xBF) { return byte(k) >= low && byte(k) <= high; };
    const unsigned lead = byte(0);
    if (lead < 0x80) return 1;
    if (lead >= 0xC2 && lead <= 0xDF) return tail(1) ? 2 : 0;
    if (lead == 0xE0) return tail(1, 0xA0) && tail(2) ? 3 : 0;
    if (lead == 0xED) return tail(1, 0x80, 0x9F) && tail(2) ? 3 : 0;
    if (lead >= 0xE1 && lead <= 0xEF) return tail(1) && tail(2) ? 3 : 0;
    if (lead == 0xF0) return tail(1, 0x90) && tail(2) && tail(3) ? 4 : 0;
    if (lead >= 0xF1 && lead <= 0xF3) return tail(1) && tail(2) && tail(3) ? 4 : 0;
    if (lead == 0xF4) return tail(1, 0x80, 0x8F) && tail(2) && tail(3) ? 4 : 0;
    return 0;
}

// C0 and DEL (one byte), C1 (U+0080 to U+009F: C2 80 to C2 9F), U+FFFE and U+FFFF (EF BF BE/BF).
bool isControlOrNonCharacter(std::string_view c) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(c[k]); };
    if (c.size() == 1) return byte(0) < 0x20 || byte(0) == 0x7F;
    if (c.size() == 2) return byte(0) == 0xC2 && byte(1) <= 0x9F;
    return c.size() == 3 && byte(0) == 0xEF && byte(1) == 0xBF && byte(2) >= 0xBE;
}

// The code point of a well-formed UTF-8 character.
char32_t codePoint(std::string_view c) {
    const auto byte = [&](std::size_t k) { return char32_t(static_cast<unsigned char>(c[k])); };
    if (c.size() == 1) return byte(0);
    if (c.size() == 2) return (byte(0) & 0x1F) << 6 | (byte(1) & 0x3F);
    if (c.size() == 3) return (byte(0) & 0x0F) << 12 | (byte(1) & 0x3F) << 6 | (byte(2) & 0x3F);
    return (byte(0) & 0x07) << 18 | (byte(1) & 0x3F) << 12 | (byte(2) & 0x3F) << 6 | (byte(3) & 0x3F);
}

// What shows as nothing, or moves the text around it: Unicode's format characters (category Cf: the
// bidi embeddings, overrides and isolates, LRM, RLM, ALM, zero-width spaces and joiners, the word
// joiner, the byte order mark, the tags...), its default-ignorable code points (variation selectors,
// Hangul fillers, the combining grapheme joiner...) and the line and paragraph separators U+2028 and
// U+2029. A name made of U+202E and "gnissim" would print as "missing", and reverse what follows it.
bool isInvisible(char32_t c) {
    static constexpr char32_t kRanges[][2] = {
        {0xAD, 0xAD},       {0x34F, 0x34F},     {0x600, 0x605},     {0x61C, 0x61C},     {0x6DD, 0x6DD},
        {0x70F, 0x70F},     {0x890, 0x891},     {0x8E2, 0x8E2},     {0x115F, 0x1160},   {0x17B4, 0x17B5},
        {0x180B, 0x180F},   {0x200B, 0x200F},   {0x2028, 0x202E},   {0x2060, 0x206F},   {0x3164, 0x3164},
        {0xFE00, 0xFE0F},   {0xFEFF, 0xFEFF},   {0xFFA0, 0xFFA0},   {0xFFF0, 0xFFFB},   {0x110BD, 0x110BD},
        {0x110CD, 0x110CD}, {0x13430, 0x1343F}, {0x1BCA0, 0x1BCA3}, {0x1D173, 0x1D17A}, {0xE0000, 0xE0FFF}};
    for (const auto& range : kRanges)
        if (c >= range[0] && c <= range[1]) return true;
    return false;
}

void appendHex(std::string& out, std::string_view bytes) {
    for (const char b : bytes) {
        char hex[5];
        std::snprintf(hex, sizeof hex, "\\x%02X", static_cast<unsigned char>(b));
        out += hex;
    }
}

} // namespace

std::string printableText(std::string_view text, TextForm form) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t length = characterLength(text, at);
        const std::string_view c = text.substr(at, length == 0 ? 1 : length);
        at += c.size();
        const char first = c[0];
        if (form == TextForm::Message && (first == '\n' || first == '\t' || first == '\r')) out += first;
        else if (form == TextForm::Name && first == '\n') out += "\\n";
        else if (form == TextForm::Name && first == '\t') out += "\\t";
        else if (form == TextForm::Name && first == '\r') out += "\\r";
        else if (form == TextForm::Name && first == '\\') out += "\\\\";
        else if (length == 0 || isControlOrNonCharacter(c) || isInvisible(codePoint(c))) appendHex(out, c);
        else out += c;
    }
    return out;
}

std::string printableName(std::string_view name) { return printableText(name, TextForm::Name); }

std::string printablePath(const std::filesystem::path& path) { return printableName(path.generic_string()); }

} // namespace raylab
