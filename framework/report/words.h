#pragma once
// The report's language: its sentences are the [report_page] messages of the catalogues
// (framework/messages/*.toml), its numbers written by the language's typography.

#include "src/messages.h"

#include <string>
#include <string_view>

namespace raylab::report {

struct Words {
    Language language;

    // The message report_page.`id` in the report's language, each {name} replaced by its argument.
    std::string text(std::string_view id, MessageArgs args = {}) const;
    const char* code() const { return languageCode(language); } // "en", "fr"
};

// English unless `lang` is "fr".
const Words& wordsFor(const std::string& lang);

// `value` with `digits` decimals (-1: the shortest exact form), a decimal comma in French.
std::string number(double value, int digits, const Words& words);

// "0.005 s", "0,005 s".
std::string seconds(double value, const Words& words);

} // namespace raylab::report
