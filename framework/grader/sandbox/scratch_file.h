#pragma once
// Reading back what an untrusted program left in a folder it could write (an agent's stderr.txt, a
// compiler's dependency file). The program may have replaced the file with a link to any file the
// grader can read, a FIFO that never ends a read, a device that never ends either (/dev/zero), or a
// hard link to another file: none of them is followed, opened for long, or read past a cap.

#include <cstddef>
#include <filesystem>
#include <string>

namespace raylab::grader {

struct ScratchFile {
    bool found = false;   // false: there is no such file (nothing was read, nothing is wrong)
    bool refused = false; // a link, a FIFO, a device, a folder or a file with other hard links: never read
    std::string text;     // what was read: at most `cap` bytes (the file's first or last ones)
    bool cut = false;     // the file held more than `cap` bytes
};

enum class ScratchKeep { head, tail };

// Opens `file` without following a link and without blocking (O_NOFOLLOW | O_NONBLOCK), reads it only
// when fstat says it is a regular file with a single link, and then at most `cap` bytes of it (its
// first or last ones, `keep`). With `trim`, a longer file is cut down to those bytes on disk too, so
// that spam does not stay in the grader's folders. Windows: the same checks by the file's status.
ScratchFile readScratchFile(const std::filesystem::path& file, std::size_t cap, ScratchKeep keep = ScratchKeep::head,
                            bool trim = false);

} // namespace raylab::grader
