#include "src/messages.h"
#include "src/windows_api.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace raylab {

// The catalogues' text, generated from framework/messages/*.toml (framework/CMakeLists.txt): parts
// to join, then a null pointer.
extern const char* const kMessagesEn[];
extern const char* const kMessagesFr[];

namespace {

std::optional<Language>& chosenLanguage() {
    static std::optional<Language> chosen;
    return chosen;
}

void flatten(const toml::table& table, const std::string& prefix, std::map<std::string, std::string>& out) {
    for (const auto& [key, node] : table) {
        const std::string id = prefix + std::string(key.str());
        if (const toml::table* inner = node.as_table()) flatten(*inner, id + ".", out);
        else if (const auto* text = node.as_string()) out[id] = text->get();
        else throw std::logic_error("message catalogue: " + id + " is neither a text nor a table");
    }
}

// The catalogue's text is its parts one after the other, each after a line "#@raylab-messages FILE"
// (framework/CMakeLists.txt): framework/messages/<language>.toml, then each lab's own. Each part is a
// TOML document; an id in two parts is an error naming both.
std::map<std::string, std::string> parseCatalogue(std::string_view text) {
    constexpr std::string_view kMarker = "#@raylab-messages ";
    std::map<std::string, std::string> out, fileOf;
    for (std::size_t at = text.find(kMarker); at != std::string_view::npos;) {
        const std::size_t end = text.find('\n', at);
        const std::string file(text.substr(at + kMarker.size(), end - at - kMarker.size()));
        const std::size_t next = text.find(kMarker, end);
        const std::string_view part = text.substr(end + 1, next == std::string_view::npos ? next : next - end - 1);
        std::map<std::string, std::string> own;
        try {
            flatten(toml::parse(part, file), "", own);
        } catch (const toml::parse_error& e) {
            throw std::logic_error(file + ":" + std::to_string(e.source().begin.line) + ": " +
                                   std::string(e.description()));
        }
        for (auto& [id, message] : own) {
            if (const auto [first, added] = fileOf.emplace(id, file); !added)
                throw std::logic_error(file + ": the message " + id + " is also in " + first->second);
            out[id] = std::move(message);
        }
        at = next;
    }
    return out;
}

} // namespace

std::string joinedText(const char* const* parts) {
    std::string text;
    for (; *parts != nullptr; ++parts) text += *parts;
    return text;
}

Language language() { return chosenLanguage() ? *chosenLanguage() : languageFromEnvironment(); }

void setLanguage(Language language) { chosenLanguage() = language; }

std::optional<Language> parseLanguage(std::string_view name) {
    if (name == "en") return Language::En;
    if (name == "fr") return Language::Fr;
    return std::nullopt;
}

Language languageFromEnvironment() {
    for (const char* variable : {"LC_ALL", "LC_MESSAGES", "LANG"}) {
        const char* value = std::getenv(variable);
        if (value == nullptr || *value == '\0') continue;
        const std::string_view v(value);
        return v == "fr" || v.substr(0, 3) == "fr_" || v.substr(0, 3) == "fr." ? Language::Fr : Language::En;
    }
#ifdef _WIN32
    // A French Windows sets none of these: its user's display language says it.
    if (PRIMARYLANGID(GetUserDefaultUILanguage()) == LANG_FRENCH) return Language::Fr;
#endif
    return Language::En;
}

const char* languageCode(Language language) { return language == Language::Fr ? "fr" : "en"; }

const std::map<std::string, std::string>& messageCatalogue(Language language) {
    static const std::map<std::string, std::string> en = parseCatalogue(joinedText(kMessagesEn));
    static const std::map<std::string, std::string> fr = parseCatalogue(joinedText(kMessagesFr));
    return language == Language::Fr ? fr : en;
}

std::string titleInLanguage(const std::string& name) {
    const auto& catalogue = messageCatalogue(language());
    const auto found = catalogue.find("check_title." + name);
    return found != catalogue.end() ? found->second : name;
}

namespace {

// Whether `count` takes the singular (CLDR's "one"): 1 in English; 0 and 1 in French ("0 figure",
// "1,5 pixel"), that is, any number below 2.
bool isOne(Language language, const std::string& count) {
    std::string number = count;
    for (char& c : number)
        if (c == ',') c = '.';
    char* end = nullptr;
    const double value = std::strtod(number.c_str(), &end);
    if (end == number.c_str()) throw std::logic_error("plural of '" + count + "', which is not a number");
    return language == Language::Fr ? std::abs(value) < 2. : value == 1.;
}

} // namespace

std::string placeholderProblem(std::string_view text) {
    for (std::size_t k = 0; k < text.size(); ++k) {
        if (text[k] == '}' && k + 1 < text.size() && text[k + 1] == '}') ++k;
        if (text[k] != '{') continue;
        if (k + 1 < text.size() && text[k + 1] == '{') {
            ++k;
            continue;
        }
        const std::size_t close = text.find('}', k);
        if (close == std::string_view::npos) return "a { that no } closes (write {{ for a brace)";
        const std::string_view inside = text.substr(k + 1, close - k - 1);
        const std::size_t bars = std::size_t(std::count(inside.begin(), inside.end(), '|'));
        const std::string_view name = inside.substr(0, inside.find('|'));
        const bool isName = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
        });
        if (!isName || (bars != 0 && bars != 2)) {
            std::string problem(1, '{'); // not "{" + string: GCC 12 warns wrongly there (-Wrestrict)
            problem.append(inside).append("} is not a placeholder: {name} or {name|one|other} (write {{ for a brace)");
            return problem;
        }
        k = close;
    }
    return "";
}

std::string tr(Language language, std::string_view id, MessageArgs args) {
    const auto& catalogue = messageCatalogue(language);
    const auto found = catalogue.find(std::string(id));
    if (found == catalogue.end()) throw std::logic_error("no message " + std::string(id));
    const std::string& text = found->second;
    std::string out;
    for (std::size_t k = 0; k < text.size();) {
        const std::size_t open = text.find_first_of("{}", k);
        if (open == std::string::npos) {
            out += text.substr(k);
            break;
        }
        out += text.substr(k, open - k);
        // {{ and }} are a brace.
        if (open + 1 < text.size() && text[open + 1] == text[open]) {
            out += text[open];
            k = open + 2;
            continue;
        }
        const std::size_t close = text[open] == '{' ? text.find('}', open) : std::string::npos;
        if (close == std::string::npos) { // a lone brace: as written (placeholderProblem names it)
            out += text[open];
            k = open + 1;
            continue;
        }
        // {name} is the argument; {name|one|other} the word that agrees with the number `name`.
        const std::string_view inside = std::string_view(text).substr(open + 1, close - open - 1);
        const std::size_t bar = inside.find('|');
        const std::string_view name = inside.substr(0, bar);
        bool replaced = false;
        for (const auto& [key, value] : args)
            if (key == name) {
                if (bar == std::string_view::npos) out += value;
                else {
                    const std::string_view forms = inside.substr(bar + 1);
                    const std::size_t second = forms.find('|');
                    out += isOne(language, value) ? forms.substr(0, second) : forms.substr(second + 1);
                }
                replaced = true;
                break;
            }
        if (!replaced) throw std::logic_error("message " + std::string(id) + ": no value for {" + std::string(name) + "}");
        k = close + 1;
    }
    return out;
}

std::string tr(std::string_view id, MessageArgs args) { return tr(language(), id, args); }

namespace {

std::string withDecimalSeparator(std::string number) {
    if (language() == Language::Fr)
        for (char& c : number)
            if (c == '.') c = ',';
    return number;
}

} // namespace

std::string formatNumber(double value, int significant) {
    char text[48];
    std::snprintf(text, sizeof text, "%.*g", significant, value);
    return withDecimalSeparator(text);
}

std::string formatFixed(double value, int decimals, bool sign) {
    char text[48];
    std::snprintf(text, sizeof text, sign ? "%+.*f" : "%.*f", decimals, value);
    return withDecimalSeparator(text);
}

} // namespace raylab
