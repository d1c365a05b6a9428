#pragma once
// Values registered by name, each with the line that registered it: the integrators, the probes, the
// labs' checks and figure steps all add themselves from their own files, at static initialisation.
// A name registered twice is an error naming both lines (two labs would answer to one name).
//
// Its owner builds it on first use, in a function-local static, because registrars in other files
// may run before the owner's own globals are built:
//
//   NameRegistry<ProbeFunction>& functions() { static NameRegistry<ProbeFunction> r("probe function"); return r; }

#include "src/source_place.h"

#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace raylab {

template <class T>
class NameRegistry {
public:
    struct Entry {
        T value;
        SourcePlace where;
    };

    // `kind` says what it holds, in its errors ("integrator", "probe").
    explicit NameRegistry(std::string kind) : m_kind(std::move(kind)) {}
    NameRegistry(const NameRegistry&) = delete;
    NameRegistry& operator=(const NameRegistry&) = delete;

    // Adds `name`; the entry stays where it is for the life of the registry. Throws std::logic_error
    // naming both places when the name is taken. In English: it runs before main, where the message
    // catalogues may not be built yet.
    const Entry& add(const std::string& name, T value, SourcePlace where) {
        const auto [at, added] = m_entries.try_emplace(name, Entry{std::move(value), where});
        if (!added)
            throw std::logic_error(where.shown() + ": the name '" + name + "' (" + m_kind +
                                   ") is registered twice, first at " + at->second.where.shown());
        return at->second;
    }

    // The entry of that name; nullptr when there is none.
    const Entry* find(std::string_view name) const {
        const auto at = m_entries.find(name);
        return at != m_entries.end() ? &at->second : nullptr;
    }

    // Every registered name, sorted.
    std::vector<std::string> names() const {
        std::vector<std::string> names;
        names.reserve(m_entries.size());
        for (const auto& entry : m_entries)
            names.push_back(entry.first);
        return names;
    }

private:
    std::string m_kind;
    std::map<std::string, Entry, std::less<>> m_entries; // sorted by name, entries never move
};

} // namespace raylab

// Declares, at namespace scope, a registrar of type `Type` named after its line (one per line),
// built with the arguments that follow: what the RAYLAB_REGISTER_* macros expand to.
#define RAYLAB_REGISTRAR_NAME_(line) raylabRegistrar##line
#define RAYLAB_REGISTRAR_NAME(line) RAYLAB_REGISTRAR_NAME_(line)
#define RAYLAB_REGISTRAR(Type) static const Type RAYLAB_REGISTRAR_NAME(__LINE__)
