#pragma once
// The channels between the grader (the parent) and the grading agent (the child, running student
// code): one message a line (protocol.h), requests read from and answers written to descriptors
// (or files) the parent chose, never stdin or stdout, so whatever the student's code prints
// cannot pass for an answer.

#include <cstdio>
#include <memory>
#include <string>

namespace raylab::grader {

// A stdio stream, closed when it goes.
struct CloseStream {
    void operator()(std::FILE* stream) const { std::fclose(stream); }
};
using Stream = std::unique_ptr<std::FILE, CloseStream>;

class ResultChannel {
public:
    // fd >= 0: a descriptor the parent opened (POSIX); otherwise `file` is opened for appending.
    ResultChannel(int fd, const std::string& file);

    // Writes one line and flushes it at once, so a child that dies later loses nothing it sent.
    void send(const std::string& jsonLine);

private:
    Stream m_out;
};

class RequestChannel {
public:
    // fd >= 0: a descriptor the parent opened (POSIX); otherwise `file` is read.
    RequestChannel(int fd, const std::string& file);

    // The next line; false once the parent has sent everything.
    bool receive(std::string& line);

private:
    Stream m_in;
};

} // namespace raylab::grader
