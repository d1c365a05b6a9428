#include "watch/page_state.h"

namespace raylab::watch {

void PageState::publish(std::string json) {
    {
        const std::lock_guard lock(m_mutex);
        ++m_version;
        // The document is an object: its version goes first, before its other members.
        const std::size_t brace = json.find('{');
        const std::string rest = brace == std::string::npos ? "}" : json.substr(brace + 1);
        m_json = "{\"version\":" + std::to_string(m_version) + (rest.starts_with("}") ? "" : ",") + rest;
    }
    m_changed.notify_all();
}

std::string PageState::after(std::uint64_t seen, std::chrono::milliseconds timeout) {
    std::unique_lock lock(m_mutex);
    m_changed.wait_for(lock, timeout, [&] { return m_stopping || m_version > seen; });
    return m_json;
}

std::uint64_t PageState::version() const {
    const std::lock_guard lock(m_mutex);
    return m_version;
}

void PageState::stop() {
    {
        const std::lock_guard lock(m_mutex);
        m_stopping = true;
    }
    m_changed.notify_all();
}

} // namespace raylab::watch
