#include "report/image_sources.h"

#include <cctype>
#include <optional>
#include <system_error>

namespace raylab::report {

namespace fs = std::filesystem;

namespace {

int hexValue(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// The path a browser reads from an address: up to its query or fragment, percent escapes decoded
// (`%2e%2e` is `..` to it), `\` as `/`; nothing when it decodes to a NUL byte.
std::optional<std::string> browserPath(const std::string& address) {
    const std::string raw = address.substr(0, address.find_first_of("?#"));
    std::string path;
    for (std::size_t i = 0; i < raw.size(); ++i) {
        char c = raw[i];
        if (c == '%' && i + 2 < raw.size() && hexValue(raw[i + 1]) >= 0 && hexValue(raw[i + 2]) >= 0) {
            c = static_cast<char>(hexValue(raw[i + 1]) * 16 + hexValue(raw[i + 2]));
            i += 2;
        }
        if (c == '\0') return std::nullopt;
        path += c == '\\' ? '/' : c;
    }
    return path;
}

// `scheme:` at the start (RFC 3986: a letter, then letters, digits, `+`, `-`, `.`); a Windows drive
// (`C:`) counts as one, and is refused with the rest.
bool hasScheme(const std::string& address) {
    const std::size_t colon = address.find(':');
    if (colon == std::string::npos || colon == 0 || std::isalpha(static_cast<unsigned char>(address[0])) == 0) return false;
    for (std::size_t i = 1; i < colon; ++i) {
        const char c = address[i];
        if (std::isalnum(static_cast<unsigned char>(c)) == 0 && c != '+' && c != '-' && c != '.') return false;
    }
    return true;
}

bool inside(const fs::path& file, const fs::path& folder) {
    const fs::path relative = file.lexically_relative(folder);
    return !relative.empty() && *relative.begin() != "..";
}

} // namespace

bool imageAllowed(const std::string& address, const ImageSources& sources) {
    if (hasScheme(address)) return false;
    const std::optional<std::string> path = browserPath(address);
    if (!path || path->empty() || path->starts_with("//")) return false;
    const fs::path written(*path);
    std::error_code error;
    const fs::path file = fs::weakly_canonical(written.is_absolute() ? written : sources.page.parent_path() / written, error);
    if (error) return false;
    for (const fs::path& folder : sources.allowed) {
        const fs::path root = fs::weakly_canonical(folder, error);
        if (!error && inside(file, root)) return true;
    }
    return false;
}

} // namespace raylab::report
