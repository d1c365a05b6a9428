#include "grader/sandbox/scratch_file.h"

#ifdef _WIN32
#include <fstream>
#else
#include <cerrno>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

namespace raylab::grader {

#ifdef _WIN32

ScratchFile readScratchFile(const std::filesystem::path& file, std::size_t cap, ScratchKeep keep, bool trim) {
    namespace fs = std::filesystem;
    ScratchFile result;
    std::error_code error;
    const fs::file_status status = fs::symlink_status(file, error);
    if (error || !fs::exists(status)) return result;
    result.found = true;
    if (!fs::is_regular_file(status) || fs::hard_link_count(file, error) != 1 || error) {
        result.refused = true;
        return result;
    }
    const std::uintmax_t size = fs::file_size(file, error);
    std::ifstream in(file, std::ios::binary);
    result.cut = size > cap;
    if (result.cut && keep == ScratchKeep::tail) in.seekg(std::streamoff(size - cap));
    result.text.resize(std::min<std::uintmax_t>(size, cap));
    in.read(result.text.data(), std::streamsize(result.text.size()));
    result.text.resize(std::size_t(in.gcount()));
    if (trim && result.cut) std::ofstream(file, std::ios::binary | std::ios::trunc) << result.text;
    return result;
}

#else

namespace {

// read() until `size` bytes or the end, from `offset`.
std::string readAt(int fd, std::size_t size, off_t offset) {
    std::string text(size, '\0');
    std::size_t got = 0;
    while (got < size) {
        const ssize_t n = pread(fd, text.data() + got, size - got, offset + off_t(got));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        got += std::size_t(n);
    }
    text.resize(got);
    return text;
}

// Writes `text` over the start of the file and cuts it there.
void keepOnly(int fd, const std::string& text) {
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = pwrite(fd, text.data() + done, text.size() - done, off_t(done));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        done += std::size_t(n);
    }
    if (ftruncate(fd, off_t(done)) != 0) {
        // the file stays longer: it was read up to the cap all the same
    }
}

} // namespace

ScratchFile readScratchFile(const std::filesystem::path& file, std::size_t cap, ScratchKeep keep, bool trim) {
    ScratchFile result;
    // O_NONBLOCK: opening a FIFO for reading returns at once instead of waiting for a writer.
    const int fd = open(file.c_str(), (trim ? O_RDWR : O_RDONLY) | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) {
        result.found = errno != ENOENT && errno != ENOTDIR;
        result.refused = result.found; // ELOOP: a link; EISDIR: a folder (for writing); ENXIO: a FIFO without reader
        return result;
    }
    result.found = true;
    struct stat status {};
    if (fstat(fd, &status) != 0 || !S_ISREG(status.st_mode) || status.st_nlink != 1) {
        result.refused = true;
        close(fd);
        return result;
    }
    const std::size_t size = std::size_t(status.st_size);
    result.cut = size > cap;
    const std::size_t count = result.cut ? cap : size;
    result.text = readAt(fd, count, keep == ScratchKeep::tail ? off_t(size - count) : 0);
    if (trim && result.cut) keepOnly(fd, result.text);
    close(fd);
    return result;
}

#endif

} // namespace raylab::grader
