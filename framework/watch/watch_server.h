#pragma once
// The watch page's server (cpp-httplib): on 127.0.0.1 alone, every request under the address's random
// token and with its Host header (http_rules.h), the page's own files (embedded at build time: no
// network, no CDN), the state as a long poll, and the files of the watch's folder, nothing else.

#include "watch/page_state.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <string>

namespace raylab::watch {

// Answers the pixel inspector's question (figure, pixel): a JSON document.
using Inspector = std::function<std::string(const std::string& figure, int x, int y)>;

class WatchServer {
public:
    WatchServer(PageState& page, std::filesystem::path root, std::string token, Inspector inspector);
    ~WatchServer();
    WatchServer(const WatchServer&) = delete;
    WatchServer& operator=(const WatchServer&) = delete;

    // Binds 127.0.0.1:`port` (0: a free port the system chooses) and returns the port; throws
    // std::runtime_error naming the address when it cannot.
    int bind(int port);
    // Serves until stop() (called from another thread, before or after this starts).
    void serve();
    void stop();

    // http://127.0.0.1:PORT/TOKEN/
    std::string address() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace raylab::watch
