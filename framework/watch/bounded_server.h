#pragma once
// httplib's Server with a bounded request head. Before httplib 0.22 (Debian 12 has 0.11, Debian 13
// 0.18) httplib keeps every header a client sends, however many, and waits for them as long as each
// arrives within the read timeout: 30 MB of headers without a token cost 73 MB, never given back, and
// a client sending one line a second held a thread for ever. Here the request's line and headers are
// read first, within kMaxHeadBytes, kMaxHeadLines and kHeadTime, by a stream of our own; past a limit
// the request is answered 431 (too large) or 408 (too slow) before httplib sees it. One request per
// connection: each connection's head is bounded so.

#include <httplib.h>

#include <chrono>
#include <cstddef>

namespace raylab::watch {

// A browser's request head is under 2 KB; 64 KB leaves room for many cookies of other local servers.
constexpr std::size_t kMaxHeadBytes = 64 * 1024;
constexpr std::size_t kMaxHeadLines = 100; // the request line and 99 headers (httplib 0.22's own limit)
constexpr std::chrono::seconds kHeadTime{5};

class BoundedServer final : public httplib::Server {
    // httplib's own, private but virtual: where it reads a connection's requests.
    bool process_and_close_socket(socket_t sock) override;
};

} // namespace raylab::watch
