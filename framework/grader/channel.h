#pragma once
// The channels between the grader (the parent) and the grading agent (the child, running student
// code): one message a line (protocol.h), requests read from and answers written to descriptors
// (or files) the parent chose, never stdin or stdout, so whatever the student's code prints
// cannot pass for an answer.

#include <cstdio>
#include <string>

namespace raylab::grader {

class ResultChannel {
public:
    // fd >= 0: a descriptor the parent opened (POSIX); otherwise `file` is opened for appending.
    ResultChannel(int fd, const std::string& file);
    ~ResultChannel();
    ResultChannel(const ResultChannel&) = delete;
    ResultChannel& operator=(const ResultChannel&) = delete;

    // Writes one line and flushes it at once, so a child that dies later loses nothing it sent.
    void send(const std::string& jsonLine);

private:
    std::FILE* m_out = nullptr;
};

class RequestChannel {
public:
    // fd >= 0: a descriptor the parent opened (POSIX); otherwise `file` is read.
    RequestChannel(int fd, const std::string& file);
    ~RequestChannel();
    RequestChannel(const RequestChannel&) = delete;
    RequestChannel& operator=(const RequestChannel&) = delete;

    // The next line; false once the parent has sent everything.
    bool receive(std::string& line);

private:
    std::FILE* m_in = nullptr;
};

} // namespace raylab::grader
