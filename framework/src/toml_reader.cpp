#include "src/toml_reader.h"

#include "src/messages.h"
#include "src/text.h"

#include <algorithm>
#include <cmath>

namespace raylab {

toml::table parseTomlFile(const std::filesystem::path& file) {
    try {
        return toml::parse_file(file.string());
    } catch (const toml::parse_error& e) {
        const toml::source_position at = e.source().begin;
        throw TomlError(file.string() + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + ": " +
                        tr("toml.not_valid", {{"problem", std::string(e.description())}}));
    }
}

void TomlReader::fail(const toml::node* node, std::string_view key, const std::string& problem) const {
    const auto line = node != nullptr ? node->source().begin.line : 0;
    std::string message = m_file.string();
    if (line > 0) message += ":" + std::to_string(line);
    throw TomlError(message + ": " + tr("toml.key_problem", {{"key", std::string(key)}, {"problem", problem}}));
}

void TomlReader::missing(const toml::table& table, std::string_view where, std::string_view key) const {
    fail(&table, std::string(where) + std::string(key), tr("toml.missing"));
}

void TomlReader::wrongType(const toml::node& node, std::string_view name, const std::string& expected) const {
    fail(&node, name, tr("toml.expected", {{"expected", expected}, {"got", typeName(node)}}));
}

void TomlReader::onlyKeys(const toml::table& table, std::string_view where,
                          std::initializer_list<std::string_view> allowed) const {
    onlyKeys(table, where, std::vector<std::string_view>(allowed));
}

void TomlReader::onlyKeys(const toml::table& table, std::string_view where,
                          const std::vector<std::string_view>& allowed) const {
    for (auto&& [key, node] : table)
        if (std::find(allowed.begin(), allowed.end(), key.str()) == allowed.end()) {
            std::string known;
            for (std::string_view k : allowed) known += (known.empty() ? "" : ", ") + std::string(k);
            fail(&node, std::string(where) + std::string(key.str()), tr("toml.unknown_key", {{"known", known}}));
        }
}

std::string TomlReader::stringOf(const toml::node& node, std::string_view name) const {
    const toml::value<std::string>* s = node.as_string();
    if (s == nullptr) wrongType(node, name, tr("toml.type.string"));
    return s->get();
}

std::int64_t TomlReader::integerOf(const toml::node& node, std::string_view name, std::int64_t lo, std::int64_t hi) const {
    const toml::value<std::int64_t>* i = node.as_integer();
    if (i == nullptr) wrongType(node, name, tr("toml.type.integer"));
    if (i->get() < lo || i->get() > hi)
        fail(&node, name,
             tr("toml.out_of_range", {{"value", std::to_string(i->get())}, {"lo", std::to_string(lo)}, {"hi", std::to_string(hi)}}));
    return i->get();
}

double TomlReader::numberOf(const toml::node& node, std::string_view name) const {
    double value = 0.;
    if (const auto* f = node.as_floating_point()) value = f->get();
    else if (const auto* i = node.as_integer()) value = double(i->get());
    else wrongType(node, name, tr("toml.type.number"));
    if (!std::isfinite(value)) fail(&node, name, tr("toml.not_finite", {{"value", showNumber(value)}}));
    return value;
}

std::optional<std::string> TomlReader::string(const toml::table& table, std::string_view where, std::string_view key) const {
    const toml::node* node = table.get(key);
    if (node == nullptr) return std::nullopt;
    return stringOf(*node, std::string(where) + std::string(key));
}

std::optional<std::int64_t> TomlReader::integer(const toml::table& table, std::string_view where, std::string_view key,
                                                std::int64_t lo, std::int64_t hi) const {
    const toml::node* node = table.get(key);
    if (node == nullptr) return std::nullopt;
    return integerOf(*node, std::string(where) + std::string(key), lo, hi);
}

std::optional<double> TomlReader::number(const toml::table& table, std::string_view where, std::string_view key) const {
    const toml::node* node = table.get(key);
    if (node == nullptr) return std::nullopt;
    return numberOf(*node, std::string(where) + std::string(key));
}

std::optional<bool> TomlReader::boolean(const toml::table& table, std::string_view where, std::string_view key) const {
    const toml::node* node = table.get(key);
    if (node == nullptr) return std::nullopt;
    const toml::value<bool>* b = node->as_boolean();
    if (b == nullptr) wrongType(*node, std::string(where) + std::string(key), tr("toml.true_or_false"));
    return b->get();
}

const toml::array* TomlReader::array(const toml::table& table, std::string_view where, std::string_view key) const {
    const toml::node* node = table.get(key);
    if (node == nullptr) return nullptr;
    if (!node->is_array()) wrongType(*node, std::string(where) + std::string(key), tr("toml.type.array"));
    return node->as_array();
}

const toml::table* TomlReader::table(const toml::table& parent, std::string_view where, std::string_view key) const {
    const toml::node* node = parent.get(key);
    if (node == nullptr) return nullptr;
    if (!node->is_table())
        fail(node, std::string(where) + std::string(key), tr("toml.expected_table", {{"table", "[" + std::string(key) + "]"}}));
    return node->as_table();
}

std::vector<const toml::table*> TomlReader::tables(const toml::table& parent, std::string_view key) const {
    std::vector<const toml::table*> items;
    const toml::node* node = parent.get(key);
    if (node == nullptr) return items;
    const std::string name = "[[" + std::string(key) + "]]";
    const toml::array* list = node->as_array();
    if (list == nullptr || !list->is_array_of_tables()) fail(node, name, tr("toml.expected_tables", {{"table", name}}));
    for (const toml::node& item : *list) items.push_back(item.as_table());
    return items;
}

std::string TomlReader::text(const toml::table& table, std::string_view where, std::string_view key) const {
    const std::optional<std::string> value = string(table, where, key);
    if (!value) missing(table, where, key);
    if (value->empty()) fail(table.get(key), std::string(where) + std::string(key), tr("toml.empty"));
    return *value;
}

std::int64_t TomlReader::requiredInteger(const toml::table& table, std::string_view where, std::string_view key,
                                         std::int64_t lo, std::int64_t hi) const {
    const std::optional<std::int64_t> value = integer(table, where, key, lo, hi);
    if (!value) missing(table, where, key);
    return *value;
}

double TomlReader::requiredNumber(const toml::table& table, std::string_view where, std::string_view key) const {
    const std::optional<double> value = number(table, where, key);
    if (!value) missing(table, where, key);
    return *value;
}

std::string TomlReader::typeName(const toml::node& node) {
    switch (node.type()) {
    case toml::node_type::string: return tr("toml.type.string");
    case toml::node_type::integer: return tr("toml.type.integer");
    case toml::node_type::floating_point: return tr("toml.type.number");
    case toml::node_type::boolean: return tr("toml.type.boolean");
    case toml::node_type::array: return tr("toml.type.array");
    case toml::node_type::table: return tr("toml.type.table");
    default: return tr("toml.type.date");
    }
}

} // namespace raylab
