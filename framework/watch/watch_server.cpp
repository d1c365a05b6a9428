#include "watch/watch_server.h"

#include "watch/bounded_server.h"
#include "watch/http_rules.h"
#include "watch/templates.h"

#include "src/atomic_file.h"
#include "src/messages.h"

#include <atomic>
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

namespace raylab::watch {

namespace fs = std::filesystem;

namespace {

// A long poll waits at most this long, under the browsers' and httplib's timeouts.
constexpr std::chrono::seconds kLongPoll{20};
// The server's threads: each open tab holds one in its long poll, each slow client one until it has
// sent its request's head (at most kHeadTime) or stopped sending for kReadTimeout; httplib's default (8 on 2 cores) let 8 tabs
// or 10 slow clients keep the page from answering. Beyond kLongPolls waiting at once, a tab's poll
// waits kBusyPoll only, so tabs never take the threads the page's other requests need.
constexpr std::size_t kThreads = 48;
constexpr int kLongPolls = 24;
constexpr std::chrono::seconds kBusyPoll{2};
constexpr time_t kReadTimeoutSeconds = 2;

std::string contentType(const fs::path& file) {
    const std::string extension = file.extension().string();
    if (extension == ".png") return "image/png";
    if (extension == ".json") return "application/json";
    if (extension == ".html") return "text/html; charset=utf-8";
    return "application/octet-stream";
}

int integerParam(const httplib::Request& request, const char* name) {
    try {
        return request.has_param(name) ? std::stoi(request.get_param_value(name)) : -1;
    } catch (const std::exception&) {
        return -1;
    }
}

// The server's threads, a pool of our own: httplib's ThreadPool, inline in its header, calls OpenSSL
// where the library was built with it (Debian 13), which this program does not link. enqueue()
// returns void in httplib 0.11 (Debian 12) and bool (accepted) since.
using Enqueued = decltype(std::declval<httplib::TaskQueue&>().enqueue(std::function<void()>()));

class ServerThreads final : public httplib::TaskQueue {
public:
    explicit ServerThreads(std::size_t count) {
        for (std::size_t k = 0; k < count; ++k) m_threads.emplace_back([this] { work(); });
    }
    Enqueued enqueue(std::function<void()> task) override {
        {
            const std::lock_guard lock(m_mutex);
            m_tasks.push_back(std::move(task));
        }
        m_ready.notify_one();
        return static_cast<Enqueued>(true); // accepted (nothing when httplib asks for void)
    }
    void shutdown() override { // the tasks queued are run first
        {
            const std::lock_guard lock(m_mutex);
            m_stopping = true;
        }
        m_ready.notify_all();
        for (std::thread& t : m_threads) t.join();
    }

private:
    void work() {
        for (;;) {
            std::function<void()> task;
            {
                std::unique_lock lock(m_mutex);
                m_ready.wait(lock, [this] { return m_stopping || !m_tasks.empty(); });
                if (m_tasks.empty()) return;
                task = std::move(m_tasks.front());
                m_tasks.pop_front();
            }
            task();
        }
    }

    std::vector<std::thread> m_threads;
    std::deque<std::function<void()>> m_tasks;
    std::mutex m_mutex;
    std::condition_variable m_ready;
    bool m_stopping = false;
};

} // namespace

struct WatchServer::Impl {
    Impl(PageState& p, fs::path r, std::string t, Inspector i)
        : page(p), root(std::move(r)), token(std::move(t)), inspector(std::move(i)) {}
    PageState& page;
    fs::path root;
    std::string token;
    Inspector inspector;
    BoundedServer server; // each request's head within limits (bounded_server.h)
    int port = 0;
    // httplib's stop() does nothing to a server that is not listening yet: stop() waits for serve()
    // to have started listening, or keeps it from starting.
    std::mutex starting;
    bool stopped = false, serving = false;
    std::atomic<bool> finished{false};
    std::atomic<int> polling{0}; // the long polls waiting now

    // What the page asks under its token; false when there is no such thing.
    bool answer(const std::string& asked, const httplib::Request& request, httplib::Response& response) {
        if (asked.empty()) {
            response.set_content(templates::kWatchHtml, "text/html; charset=utf-8");
        } else if (asked == "watch.js") {
            response.set_content(templates::kWatchJs, "text/javascript; charset=utf-8");
        } else if (asked == "watch.css") {
            response.set_content(templates::kWatchCss, "text/css; charset=utf-8");
        } else if (asked == "state") {
            const long long since = request.has_param("since") ? std::atoll(request.get_param_value("since").c_str()) : -1;
            const bool room = since >= 0 && polling.fetch_add(1) < kLongPolls;
            const std::chrono::seconds wait = since < 0 ? std::chrono::seconds(0) : room ? kLongPoll : kBusyPoll;
            const std::string state = page.after(since < 0 ? 0 : std::uint64_t(since), wait);
            if (since >= 0) polling.fetch_sub(1);
            response.set_content(state, "application/json");
        } else if (asked == "inspect" && inspector) {
            response.set_content(inspector(request.get_param_value("figure"), integerParam(request, "x"), integerParam(request, "y")),
                                 "application/json");
        } else if (asked.starts_with("files/")) {
            const auto file = servedFile(root, std::string_view(asked).substr(6));
            const std::optional<std::string> bytes = file ? readWholeFile(*file) : std::nullopt;
            if (!bytes) return false;
            response.set_content(*bytes, contentType(*file).c_str());
        } else {
            return false;
        }
        return true;
    }

    void route(const httplib::Request& request, httplib::Response& response) {
        response.set_header("Cache-Control", "no-store");
        response.set_header("X-Content-Type-Options", "nosniff");
        response.set_header("Referrer-Policy", "no-referrer");
        response.set_header("Content-Security-Policy", "default-src 'self'; img-src 'self'; frame-ancestors 'none'");
        if (!hostAllowed(request.get_header_value("Host"), port)) {
            response.status = 403;
            response.set_content(tr("watch.refused_host"), "text/plain; charset=utf-8");
            return;
        }
        const auto asked = underToken(request.path, token);
        if (!asked || !answer(*asked, request, response)) {
            response.status = 404;
            response.set_content(tr("watch.not_found"), "text/plain; charset=utf-8");
        }
    }
};

WatchServer::WatchServer(PageState& page, fs::path root, std::string token, Inspector inspector)
    : m_impl(std::make_unique<Impl>(page, std::move(root), std::move(token), std::move(inspector))) {
    // httplib's default on Linux is SO_REUSEPORT, with which a second server on the same port (another
    // raylab watch given the same --port) would share it and answer half the requests: SO_REUSEADDR
    // alone (a port left in TIME_WAIT by a Ctrl-C can be taken again), and on Windows exclusive use.
    m_impl->server.set_socket_options([](socket_t sock) { // httplib.h's, at global scope
        int yes = 1;
#ifdef _WIN32
        setsockopt(sock, SOL_SOCKET, SO_EXCLUSIVEADDRUSE, reinterpret_cast<char*>(&yes), sizeof yes);
#else
        setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
#endif
    });
    m_impl->server.set_read_timeout(kReadTimeoutSeconds, 0);
    m_impl->server.set_payload_max_length(kMaxHeadBytes); // the page sends no body
    m_impl->server.new_task_queue = [] { return new ServerThreads(kThreads); };
    // Every method and path reaches route(): the rules hold for all of them, and only GET answers.
    m_impl->server.set_pre_routing_handler([this](const httplib::Request& request, httplib::Response& response) {
        if (request.method != "GET") {
            response.status = 405;
            return httplib::Server::HandlerResponse::Handled;
        }
        try {
            m_impl->route(request, response);
        } catch (const std::exception&) { // said in the console's words, never the exception's text in the answer
            response = httplib::Response();
            response.status = 500;
            response.set_header("Cache-Control", "no-store");
            response.set_content(tr("watch.not_answered"), "text/plain; charset=utf-8");
        }
        return httplib::Server::HandlerResponse::Handled;
    });
}

WatchServer::~WatchServer() = default;

int WatchServer::bind(int port) {
    const bool bound = port == 0 ? (m_impl->port = m_impl->server.bind_to_any_port("127.0.0.1")) > 0
                                 : m_impl->server.bind_to_port("127.0.0.1", m_impl->port = port);
    if (!bound) throw std::runtime_error(tr("watch.cannot_listen", {{"address", "127.0.0.1:" + std::to_string(port)}}));
    return m_impl->port;
}

void WatchServer::serve() {
    {
        const std::lock_guard lock(m_impl->starting);
        if (m_impl->stopped) return;
        m_impl->serving = true;
    }
    m_impl->server.listen_after_bind();
    m_impl->finished = true;
}

void WatchServer::stop() {
    m_impl->page.stop();
    bool serving = false;
    {
        const std::lock_guard lock(m_impl->starting);
        m_impl->stopped = true;
        serving = m_impl->serving;
    }
    if (!serving) return;
    while (!m_impl->finished && !m_impl->server.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    m_impl->server.stop();
}

std::string WatchServer::address() const {
    return "http://127.0.0.1:" + std::to_string(m_impl->port) + "/" + m_impl->token + "/";
}

} // namespace raylab::watch
