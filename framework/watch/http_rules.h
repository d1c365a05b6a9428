#pragma once
// What `raylab watch`'s server accepts, kept apart from the server so that it can be tested alone:
// a page on the loopback address is still reachable by any page the student's browser opens (DNS
// rebinding, a guessed port), so every request must name the random token of the address, come with
// the Host header of that address, and ask for a file of the watch's own folder.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace raylab::watch {

// A new random token for the address: 32 hexadecimal digits (128 bits) from the system's generator.
std::string newToken();

// Whether a request's Host header names this server: 127.0.0.1 or localhost with its port, and no
// other name (a rebound DNS name arrives with the attacker's name in Host).
bool hostAllowed(std::string_view host, int port);

// The part of `target` (a request's path, without its query) after "/<token>/"; nullopt when the
// path does not start with it. The comparison takes the same time whatever the first wrong byte.
std::optional<std::string> underToken(std::string_view target, std::string_view token);

// The regular file of `root` that `relative` (a path under the token, already %-decoded) names, or
// nullopt: an absolute path, "..", a backslash, a NUL, a hidden part, or a symbolic link on the way
// all refuse, so that nothing outside `root` is ever read.
std::optional<std::filesystem::path> servedFile(const std::filesystem::path& root, std::string_view relative);

} // namespace raylab::watch
