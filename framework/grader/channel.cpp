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

ResultChannel::~ResultChannel() {
    if (m_out) std::fclose(m_out);
}

void ResultChannel::send(const std::string& jsonLine) {
    std::fputs(jsonLine.c_str(), m_out);
    std::fputc('\n', m_out);
    std::fflush(m_out);
}

} // namespace raylab::grader
