#pragma once
// The one strict reader of the project's TOML files (scene files, lab.toml, the grader's mistakes
// and references): an unknown key, a value of the wrong type, a missing value or a number that is
// not finite is an error naming the file, the line, the key and what was expected.

#include <toml++/toml.h>

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace raylab {

// A TOML file that cannot be used: what() is "FILE:LINE: key: problem" ("FILE: key: problem" where
// no line applies; "FILE:LINE:COLUMN: not valid TOML: ..." for a syntax error).
class TomlError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The whole file, parsed; a syntax error is a TomlError.
toml::table parseTomlFile(const std::filesystem::path& file);

// Reads the tables of one file. A key is named `where` + key: `where` is the table's name as its
// file writes it with a space after it ("[camera] ", "[[figure]] #2 "), empty at the top level.
class TomlReader {
public:
    explicit TomlReader(std::filesystem::path file) : m_file(std::move(file)) {}

    const std::filesystem::path& file() const { return m_file; }

    // Throws TomlError at the line of `node` (none when null) about `key`.
    [[noreturn]] void fail(const toml::node* node, std::string_view key, const std::string& problem) const;

    // Refuses a key of `table` outside `allowed`, naming it and the allowed keys.
    void onlyKeys(const toml::table& table, std::string_view where, std::initializer_list<std::string_view> allowed) const;
    void onlyKeys(const toml::table& table, std::string_view where, const std::vector<std::string_view>& allowed) const;

    // A value of the table: nullopt (or null) when the key is absent, a TomlError when it has another type.
    std::optional<std::string> string(const toml::table& table, std::string_view where, std::string_view key) const;
    std::optional<std::int64_t> integer(const toml::table& table, std::string_view where, std::string_view key,
                                        std::int64_t lo, std::int64_t hi) const;
    std::optional<double> number(const toml::table& table, std::string_view where, std::string_view key) const;
    std::optional<bool> boolean(const toml::table& table, std::string_view where, std::string_view key) const;
    const toml::array* array(const toml::table& table, std::string_view where, std::string_view key) const;
    const toml::table* table(const toml::table& parent, std::string_view where, std::string_view key) const;
    // The [[key]] tables, in order (none when absent).
    std::vector<const toml::table*> tables(const toml::table& parent, std::string_view key) const;

    // Required values: a missing one is a TomlError at the table's line.
    std::string text(const toml::table& table, std::string_view where, std::string_view key) const; // not empty
    std::int64_t requiredInteger(const toml::table& table, std::string_view where, std::string_view key,
                                 std::int64_t lo, std::int64_t hi) const;
    double requiredNumber(const toml::table& table, std::string_view where, std::string_view key) const;

    // One value, named `name` in errors (an array's item, or a value already found).
    std::string stringOf(const toml::node& node, std::string_view name) const;
    std::int64_t integerOf(const toml::node& node, std::string_view name, std::int64_t lo, std::int64_t hi) const;
    double numberOf(const toml::node& node, std::string_view name) const; // an integer or a float, finite

    // "a string", "an integer" ... in the current language.
    static std::string typeName(const toml::node& node);

private:
    [[noreturn]] void missing(const toml::table& table, std::string_view where, std::string_view key) const;
    [[noreturn]] void wrongType(const toml::node& node, std::string_view name, const std::string& expected) const;

    std::filesystem::path m_file;
};

} // namespace raylab
