#include "report/title_block.h"

#include "src/atomic_file.h"
#include "report/templates.h"

#include <toml++/toml.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <stdexcept>

namespace raylab::report {

namespace {

constexpr const char* kKeys[] = {"name", "group", "course", "date"};

std::string where(const std::filesystem::path& file, const toml::source_region& at) {
    return file.string() + ":" + std::to_string(at.begin.line);
}

std::string today() {
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm local{};
#ifdef _WIN32
    localtime_s(&local, &now); // Windows' localtime_r, its arguments swapped
#else
    localtime_r(&now, &local);
#endif
    char text[16];
    std::strftime(text, sizeof text, "%Y-%m-%d", &local);
    return text;
}

// report.toml as the first run creates it, in the report's language.
const char* createdFile(Language language) {
    return language == Language::Fr ? templates::kReportFrToml : templates::kReportEnToml;
}

// A placeholder is the value the created file holds ("Your name", "Votre nom"...).
bool isPlaceholder(const std::string& key, const std::string& value) {
    for (Language language : {Language::En, Language::Fr}) {
        const std::string created = createdFile(language);
        if (created.find(key + " = \"" + value + "\"") != std::string::npos && !value.empty()) return true;
    }
    return false;
}

toml::table parse(const std::filesystem::path& file) {
    try {
        return toml::parse_file(file.string());
    } catch (const toml::parse_error& e) {
        throw std::runtime_error(where(file, e.source()) + ": " + std::string(e.description()));
    }
}

} // namespace

TitleBlock readTitleBlock(const std::filesystem::path& file, const Words& words) {
    if (!std::filesystem::exists(file)) writeFileAtomically(file, createdFile(words.language));
    const toml::table table = parse(file);
    for (const auto& [key, node] : table) {
        const bool known = std::find(std::begin(kKeys), std::end(kKeys), key.str()) != std::end(kKeys);
        if (!known)
            throw std::runtime_error(where(file, node.source()) + ": " +
                                     words.text("title_unknown_key", {{"key", std::string(key.str())}}));
        if (!node.is_string())
            throw std::runtime_error(where(file, node.source()) + ": " +
                                     words.text("title_not_string", {{"key", std::string(key.str())}}));
    }
    TitleBlock block;
    std::string* fields[] = {&block.name, &block.group, &block.course, &block.date};
    for (std::size_t k = 0; k < std::size(kKeys); ++k) {
        *fields[k] = table[kKeys[k]].value_or(std::string());
        if (isPlaceholder(kKeys[k], *fields[k])) block.placeholders = true;
    }
    if (block.name.empty() || block.group.empty() || block.course.empty()) block.placeholders = true;
    if (block.date.empty()) block.date = today();
    return block;
}

} // namespace raylab::report
