#pragma once
// What the watch page shows, shared between the thread that builds and grades and the server's
// threads: a JSON document with a version that grows at each change. A page asks for the version
// after the one it has and waits (a long poll) until there is one, so that it refreshes by itself.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>

namespace raylab::watch {

class PageState {
public:
    // Publishes a new document (JSON text, without its version: "version" is added) and wakes the waiters.
    void publish(std::string json);
    // The newest document once its version is above `seen`, or after `timeout` (then the current
    // one, which the page takes as "nothing new"), or at once when the watch is stopping.
    std::string after(std::uint64_t seen, std::chrono::milliseconds timeout);
    std::uint64_t version() const;
    // Wakes every waiter for good: the server is about to stop.
    void stop();

private:
    mutable std::mutex m_mutex;
    std::condition_variable m_changed;
    std::uint64_t m_version = 0;
    std::string m_json = "{}";
    bool m_stopping = false;
};

} // namespace raylab::watch
