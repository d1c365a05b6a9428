#include "watch/http_rules.h"

#include <random>

namespace raylab::watch {

namespace fs = std::filesystem;

std::string newToken() {
    std::random_device device;
    static constexpr char kHex[] = "0123456789abcdef";
    std::string token;
    for (int k = 0; k < 4; ++k) {
        const std::uint32_t bits = device();
        for (int shift = 28; shift >= 0; shift -= 4) token += kHex[(bits >> shift) & 0xfu];
    }
    return token;
}

bool hostAllowed(std::string_view host, int port) {
    const std::size_t colon = host.rfind(':');
    if (colon == std::string_view::npos) return false;
    const std::string_view name = host.substr(0, colon);
    return (name == "127.0.0.1" || name == "localhost") && host.substr(colon + 1) == std::to_string(port);
}

std::optional<std::string> underToken(std::string_view target, std::string_view token) {
    const std::size_t length = token.size() + 2; // "/token/"
    if (token.empty() || target.size() < length) return std::nullopt;
    unsigned char differ = (target[0] != '/') | (target[length - 1] != '/');
    for (std::size_t k = 0; k < token.size(); ++k) differ |= static_cast<unsigned char>(target[k + 1] ^ token[k]);
    if (differ != 0) return std::nullopt;
    return std::string(target.substr(length));
}

std::optional<fs::path> servedFile(const fs::path& root, std::string_view relative) {
    if (relative.empty() || relative.find('\0') != std::string_view::npos || relative.find('\\') != std::string_view::npos)
        return std::nullopt;
    const fs::path asked{std::string(relative)};
    if (asked.is_absolute() || asked.has_root_name()) return std::nullopt;
    fs::path file = root;
    std::error_code error;
    for (const fs::path& part : asked) {
        const std::string name = part.string();
        if (name.empty() || name.starts_with(".")) return std::nullopt; // "..", ".", hidden files
        file /= part;
        const fs::file_status status = fs::symlink_status(file, error);
        if (error || fs::is_symlink(status)) return std::nullopt;
    }
    if (!fs::is_regular_file(fs::symlink_status(file, error)) || error) return std::nullopt;
    return file;
}

} // namespace raylab::watch
