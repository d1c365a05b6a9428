#include "grader/channel.h"

#include <stdexcept>
#ifndef _WIN32
#include <unistd.h>
#endif

namespace raylab::grader {

ResultChannel::ResultChannel(int fd, const std::string& file) {
#ifndef _WIN32
    if (fd >= 0) {
        // Our own copy of the descriptor: closing the FILE leaves the parent's number alone.
        m_out = fdopen(dup(fd), "w");
        if (!m_out) throw std::runtime_error("agent: cannot write to result descriptor " + std::to_string(fd));
        return;
    }
#else
    (void)fd;
#endif
    m_out = std::fopen(file.c_str(), "a");
    if (!m_out) throw std::runtime_error("agent: cannot open the result file " + file);
}

RequestChannel::RequestChannel(int fd, const std::string& file) {
#ifndef _WIN32
    if (fd >= 0) {
        m_in = fdopen(dup(fd), "r");
        if (!m_in) throw std::runtime_error("agent: cannot read the request descriptor " + std::to_string(fd));
        return;
    }
#else
    (void)fd;
#endif
    m_in = std::fopen(file.c_str(), "r");
    if (!m_in) throw std::runtime_error("agent: cannot open the request file " + file);
}

RequestChannel::~RequestChannel() {
    if (m_in) std::fclose(m_in);
}

bool RequestChannel::receive(std::string& line) {
    line.clear();
    for (int c; (c = std::fgetc(m_in)) != EOF;) {
        if (c == '\n') return true;
        line += char(c);
    }
    return !line.empty();
}

ResultChannel::~ResultChannel() {
    if (m_out) std::fclose(m_out);
}

void ResultChannel::send(const std::string& jsonLine) {
    std::fputs(jsonLine.c_str(), m_out);
    std::fputc('\n', m_out);
    std::fflush(m_out);
}

} // namespace raylab::grader
