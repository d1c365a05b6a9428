#pragma once
// Files read whole, and written whole or not at all: every output of raylab (PNG, CSV, JSON, HTML,
// Markdown, SVG, TOML) goes through here, so a full disk, a read-only folder or an interrupted run
// never leaves a truncated file behind or passes unnoticed.

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>

namespace raylab {

// A file that could not be written: what() names the file and the reason ("No space left on device"),
// code() the system's error when there is one (a class run stops on a full disk, course/class_run.h).
class WriteError : public std::runtime_error {
public:
    explicit WriteError(const std::string& what, std::error_code code = {}) : std::runtime_error(what), m_code(code) {}
    std::error_code code() const { return m_code; }

private:
    std::error_code m_code;
};

// Writes `bytes` to a temporary file in the folder of `file` (created if needed), flushes it to the
// disk, then renames it over `file`: readers see the old file or the whole new one, never a part.
// A symbolic link is followed (its target is replaced). A `file` that exists but is not a regular
// file (a device such as /dev/null, a pipe) is written in place, every step checked. Throws
// WriteError, after removing the temporary file, when any step fails; the old file is then intact.
void writeFileAtomically(const std::filesystem::path& file, std::string_view bytes);

// The bytes of `file`; nothing when it cannot be opened or read to its end (each caller says why
// in its own words).
std::optional<std::string> readWholeFile(const std::filesystem::path& file);

// Copies a regular file to `to` as writeFileAtomically writes it; throws std::runtime_error naming
// `from` when it cannot be read, WriteError when `to` cannot be written.
void copyFileAtomically(const std::filesystem::path& from, const std::filesystem::path& to);

} // namespace raylab
