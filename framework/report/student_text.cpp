#include "report/student_text.h"

#include <cstdint>
#include <cstdio>
#include <regex>
#include <set>
#include <sstream>

namespace raylab::report {

namespace {

const std::regex kBegin(R"(^\s*<!--\s*raylab:(student|generated)\s+([A-Za-z0-9_.-]+)(\s+hash=([0-9a-f]+))?\s*-->\s*$)");
const std::regex kEnd(R"(^\s*<!--\s*raylab:end\s*-->\s*$)");

// A generated part's fingerprint: a part whose text no longer matches it was edited by the student.
std::string fingerprint(const std::string& text) {
    std::uint64_t h = 14695981039346656037ULL; // FNV-1a
    for (unsigned char c : text) h = (h ^ c) * 1099511628211ULL;
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
    return hex;
}

bool blank(const std::string& text) { return text.find_first_not_of(" \t\r\n") == std::string::npos; }

// Text without its leading and trailing blank lines, ending with one newline (or empty).
std::string trimmed(const std::string& text) {
    const std::size_t first = text.find_first_not_of("\r\n");
    if (first == std::string::npos || blank(text)) return "";
    const std::size_t last = text.find_last_not_of(" \t\r\n");
    const std::size_t lineStart = text.rfind('\n', first);
    const std::size_t begin = lineStart == std::string::npos ? 0 : lineStart + 1;
    return text.substr(begin, last + 1 - begin) + "\n";
}

struct Reader {
    explicit Reader(const Words& w) : words(w) {}

    const Words& words;
    PreviousText found;
    enum class In { Nothing, Generated, Student } in = In::Nothing;
    std::string key, hash, text;
    int lineNumber = 0, begin = 0, firstText = 0; // the current line; the segment's marker; its first text line

    void close() {
        const std::string body = trimmed(text);
        using Origin = UnplacedText::Origin;
        if (in == In::Student) {
            found.student.push_back({Segment::Kind::Student, key, body});
            found.studentLines.push_back(begin);
        } else if (in == In::Generated && !hash.empty() && fingerprint(body) != hash && !body.empty())
            found.unplaced.push_back({Origin::EditedGenerated, key, begin,
                                      words.text("edited_generated", {{"section", key}}) + "\n\n" + body});
        else if (in == In::Nothing && !body.empty())
            found.unplaced.push_back({Origin::OutsideMarkers, "", firstText, body});
        in = In::Nothing;
        key.clear();
        hash.clear();
        text.clear();
        firstText = 0;
    }

    void line(const std::string& l) {
        ++lineNumber;
        std::smatch m;
        if (std::regex_match(l, m, kBegin)) { // a begin also ends a segment whose end marker was deleted
            close();
            in = m[1] == "student" ? In::Student : In::Generated;
            key = m[2];
            hash = m[4];
            begin = lineNumber;
        } else if (std::regex_match(l, kEnd)) {
            close();
        } else {
            if (firstText == 0 && !blank(l)) firstText = lineNumber;
            text += l + "\n";
        }
    }
};

} // namespace

PreviousText readPreviousText(const std::string& markdown, const Words& words) {
    Reader reader(words);
    std::istringstream in(markdown);
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line.back() == '\r') line.pop_back(); // an editor's CRLF is not an edit
        reader.line(line);
    }
    reader.close();
    return reader.found;
}

std::vector<Segment> placeStudentText(std::vector<Segment> fresh, const PreviousText& previous, const Words& words,
                                      std::vector<UnplacedText>* moved) {
    std::set<std::string> written;
    for (const Segment& s : fresh)
        if (s.kind == Segment::Kind::Student) written.insert(s.key);
    std::set<std::string> placed;
    std::string kept;
    const auto keep = [&](const std::string& text) {
        if (blank(text)) return;
        if (!kept.empty()) kept += '\n';
        kept += trimmed(text);
    };
    const auto tell = [&](UnplacedText piece, const std::string& text) {
        if (moved != nullptr && !blank(text)) moved->push_back(std::move(piece));
    };
    for (std::size_t k = 0; k < previous.student.size(); ++k) {
        const Segment& old = previous.student[k];
        const int line = k < previous.studentLines.size() ? previous.studentLines[k] : 0;
        if (old.key == kKeptKey) keep(old.text);
        else if (written.count(old.key) == 0 || placed.count(old.key) != 0) { // gone, or a second copy
            keep(words.text("kept_from", {{"section", old.key}}) + "\n\n" + old.text);
            const auto origin =
                written.count(old.key) == 0 ? UnplacedText::Origin::SectionGone : UnplacedText::Origin::SecondCopy;
            tell({origin, old.key, line, ""}, old.text);
        } else {
            for (Segment& s : fresh)
                if (s.kind == Segment::Kind::Student && s.key == old.key) s.text = old.text;
            placed.insert(old.key);
        }
    }
    for (const UnplacedText& piece : previous.unplaced) {
        keep(piece.text);
        tell(piece, piece.text);
    }
    if (!kept.empty()) {
        fresh.push_back({Segment::Kind::Generated, "kept-heading",
                         std::string("## ") + words.text("kept") + "\n\n" + words.text("kept_intro") + "\n"});
        fresh.push_back({Segment::Kind::Student, kKeptKey, kept});
    }
    return fresh;
}

std::string movedTextNotice(const std::vector<UnplacedText>& moved, const std::string& file, const Words& words) {
    if (moved.empty()) return "";
    const std::string count = std::to_string(moved.size());
    std::string notice = words.text("moved", {{"count", count}, {"file", file}, {"kept", words.text("kept")}}) + "\n";
    for (const UnplacedText& piece : moved) {
        const char* id = piece.origin == UnplacedText::Origin::OutsideMarkers    ? "moved_outside"
                         : piece.origin == UnplacedText::Origin::EditedGenerated ? "moved_edited"
                         : piece.origin == UnplacedText::Origin::SectionGone     ? "moved_gone"
                                                                                  : "moved_copy";
        const MessageArgs args{{"file", file}, {"line", std::to_string(piece.line)}, {"section", piece.section}};
        notice += "  " + words.text(id, args) + "\n";
    }
    return notice;
}

std::string toMarkdown(const std::vector<Segment>& document) {
    std::string out;
    for (const Segment& s : document) {
        const std::string body = trimmed(s.text);
        if (s.kind == Segment::Kind::Student) out += "<!-- raylab:student " + s.key + " -->\n";
        else out += "<!-- raylab:generated " + s.key + " hash=" + fingerprint(body) + " -->\n";
        out += body + "<!-- raylab:end -->\n\n";
    }
    return out;
}

} // namespace raylab::report
