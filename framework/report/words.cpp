#include "report/words.h"

#include <cstdio>
#include <utility>

namespace raylab::report {

std::string Words::text(std::string_view id, MessageArgs args) const {
    return tr(language, "report_page." + std::string(id), std::move(args));
}

const Words& wordsFor(const std::string& lang) {
    static constexpr Words kEnglish{Language::En}, kFrench{Language::Fr};
    return lang == "fr" ? kFrench : kEnglish;
}

std::string number(double value, int digits, const Words& words) {
    char text[64];
    if (digits < 0) std::snprintf(text, sizeof text, "%g", value);
    else std::snprintf(text, sizeof text, "%.*f", digits, value);
    std::string out = text;
    if (words.language == Language::Fr)
        for (char& c : out)
            if (c == '.') c = ',';
    return out;
}

std::string seconds(double value, const Words& words) { return number(value, 3, words) + " s"; }

} // namespace raylab::report
