#include "grader/sandbox/channel.h"

#include <stdexcept>
#ifndef _WIN32
#include <unistd.h>
#endif

namespace raylab::grader {

namespace {

// A stream on our own copy of the descriptor `fd` when it is >= 0 (POSIX: closing the stream leaves
// the parent's number alone), else on `file`; throws naming the `channel` ("result", "request").
Stream openChannel(int fd, const std::string& file, const char* mode, const char* fileMode, const char* channel) {
#ifndef _WIN32
    if (fd >= 0) {
        Stream stream(fdopen(dup(fd), mode));
        if (!stream)
            throw std::runtime_error(std::string("agent: cannot open the ") + channel + " descriptor " + std::to_string(fd));
        return stream;
    }
#else
    (void)fd;
    (void)mode;
#endif
    Stream stream(std::fopen(file.c_str(), fileMode));
    if (!stream) throw std::runtime_error(std::string("agent: cannot open the ") + channel + " file " + file);
    return stream;
}

} // namespace

ResultChannel::ResultChannel(int fd, const std::string& file) : m_out(openChannel(fd, file, "w", "a", "result")) {}

RequestChannel::RequestChannel(int fd, const std::string& file) : m_in(openChannel(fd, file, "r", "r", "request")) {}

bool RequestChannel::receive(std::string& line) {
    line.clear();
    for (int c; (c = std::fgetc(m_in.get())) != EOF;) {
        if (c == '\n') return true;
        line += char(c);
    }
    return !line.empty();
}

void ResultChannel::send(const std::string& jsonLine) {
    std::fputs(jsonLine.c_str(), m_out.get());
    std::fputc('\n', m_out.get());
    std::fflush(m_out.get());
}

} // namespace raylab::grader
