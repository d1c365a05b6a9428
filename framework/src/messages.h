#pragma once
// What the student reads, in their language: one catalogue per language (framework/messages/en.toml
// and fr.toml, embedded at build time), message ids with named placeholders, and numbers written the
// language's way (French: decimal comma, a no-break space before ":" ";" "?" "!").

#include <vector>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace raylab {

enum class Language { En, Fr };

// The language messages are written in: from the environment until setLanguage is called.
Language language();
void setLanguage(Language language);
// "en" or "fr"; nullopt for anything else.
std::optional<Language> parseLanguage(std::string_view name);
// LC_ALL, else LC_MESSAGES, else LANG, the first one set: fr_* (or "fr") gives French, anything else
// English. With none set, on Windows, the user's display language (French or not); elsewhere English.
Language languageFromEnvironment();
const char* languageCode(Language language); // "en", "fr"

using MessageArgs = std::vector<std::pair<std::string_view, std::string>>;

// The message `id` in the current language, each {name} replaced by its argument, and each
// {name|one|other} by the form that agrees with the number `name` in that language ("1 figure",
// "2 figures"; French "0 figure"); {{ and }} write a brace. An unknown id or placeholder is a
// programming error: std::logic_error.
std::string tr(std::string_view id, MessageArgs args = {});
std::string tr(Language language, std::string_view id, MessageArgs args = {});

// A check's id or a lab function's name (as lab.toml writes them) as the reader sees it: its title in
// [check_title] of the language's catalogue (a check has one in each language), else the name itself.
std::string titleInLanguage(const std::string& name);

// What is wrong with a message's placeholders, "" when nothing: each { opens {name} or
// {name|one|other} (a name: letters, digits, _), or is doubled ({{) for a brace.
std::string placeholderProblem(std::string_view text);

// A language's whole catalogue: id -> text (for the tests).
const std::map<std::string, std::string>& messageCatalogue(Language language);

// Text embedded in parts (cmake/RaylabEmbedText.cmake: parts, then a null pointer), joined.
std::string joinedText(const char* const* parts);

// A number in `significant` digits, shortest form ("%g"), with the language's decimal separator.
std::string formatNumber(double value, int significant = 4);
// A number with `decimals` decimals ("%.3f"), "+" before a positive one when `sign`.
std::string formatFixed(double value, int decimals, bool sign = false);

} // namespace raylab
