#include "watch/bounded_server.h"

#include "src/messages.h"

#include <algorithm>
#include <string>

#ifdef _WIN32
#include <winsock2.h>
#include <ws2tcpip.h>
#else
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>
#endif

namespace raylab::watch {

namespace {

using Clock = std::chrono::steady_clock;

#ifdef MSG_NOSIGNAL
constexpr int kSendFlags = MSG_NOSIGNAL; // a closed peer is an error, not SIGPIPE
#else
constexpr int kSendFlags = 0; // macOS: httplib sets SO_NOSIGPIPE; Windows has no SIGPIPE
#endif

// Waits until `sock` is ready for `events` (POLLIN, POLLOUT) or `deadline`.
bool ready(socket_t sock, short events, Clock::time_point deadline) {
    for (;;) {
        // Rounded up: a deadline 0.4 ms away is waited for, not taken as passed.
        const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now()).count();
        if (left <= 0) return false;
        pollfd watched{};
        watched.fd = sock;
        watched.events = events;
#ifdef _WIN32
        const int n = WSAPoll(&watched, 1, int(left));
#else
        const int n = ::poll(&watched, 1, int(left));
        if (n < 0 && errno == EINTR) continue;
#endif
        return n > 0;
    }
}

void ipAndPort(socket_t sock, bool remote, std::string& ip, int& port) {
    sockaddr_storage address{};
    socklen_t length = sizeof address;
    auto* named = reinterpret_cast<sockaddr*>(&address);
    ip.clear();
    port = 0;
    if ((remote ? ::getpeername(sock, named, &length) : ::getsockname(sock, named, &length)) != 0) return;
    char text[INET6_ADDRSTRLEN] = {};
    if (address.ss_family == AF_INET) {
        const auto* v4 = reinterpret_cast<const sockaddr_in*>(&address);
        if (inet_ntop(AF_INET, &v4->sin_addr, text, sizeof text)) ip = text;
        port = ntohs(v4->sin_port);
    } else if (address.ss_family == AF_INET6) {
        const auto* v6 = reinterpret_cast<const sockaddr_in6*>(&address);
        if (inet_ntop(AF_INET6, &v6->sin6_addr, text, sizeof text)) ip = text;
        port = ntohs(v6->sin6_port);
    }
}

// A connection's stream as httplib reads it, which counts the head's bytes and lines as they come and
// refuses (reads fail, httplib's answer is dropped) once a limit is passed. Every generation of
// httplib's Stream is implemented (is_writable until 0.19, wait_readable, wait_writable and duration
// since 0.20), so no member is marked override: one would be wrong with some version.
class HeadBoundedStream final : public httplib::Stream {
public:
    enum class Refusal { None, TooLarge, TooSlow };

    HeadBoundedStream(socket_t sock, Clock::duration readTimeout, Clock::duration writeTimeout)
        : m_sock(sock), m_readTimeout(readTimeout), m_writeTimeout(writeTimeout), m_start(Clock::now()),
          m_headDeadline(m_start + kHeadTime) {}

    Refusal refusal() const { return m_refusal; }

    bool is_readable() const { return false; } // nothing is buffered here (its sense since 0.20)
    bool is_writable() const { return wait_writable(); }
    bool wait_readable() const { return ready(m_sock, POLLIN, Clock::now() + m_readTimeout); }
    bool wait_writable() const { return ready(m_sock, POLLOUT, Clock::now() + m_writeTimeout); }
    time_t duration() const { // in milliseconds
        return time_t(std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - m_start).count());
    }

    ssize_t read(char* ptr, size_t size) {
        if (m_refusal != Refusal::None) return -1;
        const Clock::time_point deadline = m_headDone ? Clock::now() + m_readTimeout
                                                      : std::min(Clock::now() + m_readTimeout, m_headDeadline);
        if (!ready(m_sock, POLLIN, deadline)) {
            if (!m_headDone && deadline == m_headDeadline) m_refusal = Refusal::TooSlow;
            return -1;
        }
        const auto n = ::recv(m_sock, ptr, static_cast<int>(std::min<size_t>(size, 1 << 20)), 0);
        if (n > 0 && !m_headDone) countHead(ptr, size_t(n));
        return m_refusal == Refusal::None ? ssize_t(n) : -1;
    }

    ssize_t write(const char* ptr, size_t size) {
        if (m_refusal != Refusal::None) return ssize_t(size); // httplib's 400: ours is sent instead
        if (!wait_writable()) return -1;
        return ssize_t(::send(m_sock, ptr, static_cast<int>(std::min<size_t>(size, 1 << 20)), kSendFlags));
    }

    void get_remote_ip_and_port(std::string& ip, int& port) const { ipAndPort(m_sock, true, ip, port); }
    void get_local_ip_and_port(std::string& ip, int& port) const { ipAndPort(m_sock, false, ip, port); }
    socket_t socket() const { return m_sock; }

private:
    // The head ends at its first empty line, "\r\n": httplib ends it there only (it skips a bare "\n"
    // and reads on), so every other line counts.
    void countHead(const char* bytes, size_t n) {
        for (size_t k = 0; k < n && !m_headDone; ++k) {
            if (++m_headBytes > kMaxHeadBytes) {
                m_refusal = Refusal::TooLarge;
                return;
            }
            if (bytes[k] != '\n') {
                ++m_lineBytes;
                m_lastByte = bytes[k];
                continue;
            }
            if (m_lines > 0 && m_lineBytes == 1 && m_lastByte == '\r') {
                m_headDone = true;
            } else if (++m_lines > kMaxHeadLines) {
                m_refusal = Refusal::TooLarge;
                return;
            }
            m_lineBytes = 0;
        }
    }

    socket_t m_sock;
    Clock::duration m_readTimeout, m_writeTimeout;
    Clock::time_point m_start, m_headDeadline;
    size_t m_headBytes = 0, m_lines = 0, m_lineBytes = 0;
    char m_lastByte = 0;
    bool m_headDone = false;
    Refusal m_refusal = Refusal::None;
};

void sendRefusal(socket_t sock, HeadBoundedStream::Refusal refusal) {
    const bool slow = refusal == HeadBoundedStream::Refusal::TooSlow;
    const std::string body = tr(slow ? "watch.head_too_slow" : "watch.head_too_large");
    const std::string answer = std::string(slow ? "HTTP/1.1 408 Request Timeout" : "HTTP/1.1 431 Request Header Fields Too Large") +
                               "\r\nContent-Type: text/plain; charset=utf-8\r\nContent-Length: " + std::to_string(body.size()) +
                               "\r\nConnection: close\r\nCache-Control: no-store\r\n\r\n" + body;
    // One try, without waiting: a client that does not read its answer is not waited for.
    ::send(sock, answer.data(), static_cast<int>(answer.size()), kSendFlags);
    // What the client sent beyond the limit is read and dropped for a moment: closing with unread bytes
    // resets the connection, and the client could lose the answer.
#ifdef _WIN32
    ::shutdown(sock, SD_SEND);
#else
    ::shutdown(sock, SHUT_WR);
#endif
    const Clock::time_point until = Clock::now() + std::chrono::milliseconds(200);
    char dropped[4096];
    for (size_t total = 0; total < kMaxHeadBytes * 4 && ready(sock, POLLIN, until);) {
        const auto n = ::recv(sock, dropped, sizeof dropped, 0);
        if (n <= 0) break;
        total += size_t(n);
    }
}

} // namespace

bool BoundedServer::process_and_close_socket(socket_t sock) {
    const auto seconds = [](time_t s, time_t us) { return std::chrono::seconds(s) + std::chrono::microseconds(us); };
    HeadBoundedStream stream(sock, seconds(read_timeout_sec_, read_timeout_usec_), seconds(write_timeout_sec_, write_timeout_usec_));
    // httplib's request, with the arguments of its version: since 0.12 also the two addresses.
    const auto process = [&stream](auto& server) {
        bool closed = false;
        if constexpr (requires { server.process_request(stream, true, closed, nullptr); }) {
            return server.process_request(stream, true, closed, nullptr);
        } else {
            std::string remoteIp, localIp;
            int remotePort = 0, localPort = 0;
            stream.get_remote_ip_and_port(remoteIp, remotePort);
            stream.get_local_ip_and_port(localIp, localPort);
            return server.process_request(stream, remoteIp, remotePort, localIp, localPort, true, closed, nullptr);
        }
    };
    const bool answered = process(*this);
    if (stream.refusal() != HeadBoundedStream::Refusal::None) sendRefusal(sock, stream.refusal());
#ifdef _WIN32
    ::shutdown(sock, SD_BOTH);
    ::closesocket(sock);
#else
    ::shutdown(sock, SHUT_RDWR);
    ::close(sock);
#endif
    return answered;
}

} // namespace raylab::watch
