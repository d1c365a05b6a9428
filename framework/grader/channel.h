#pragma once
// The channel from the grading agent (the child, running student code) to the grader (the parent):
// one JSON object a line, written to a descriptor or file the parent chose, never to stdout, so
// whatever the student's code prints cannot pass for a result.

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

} // namespace raylab::grader
