#include "src/atomic_file.h"

#include <atomic>
#include <cerrno>
#include <fstream>
#include <string>
#include <system_error>

#if defined(__unix__) || defined(__APPLE__)
#define RAYLAB_POSIX_FILES 1
#include <fcntl.h>
#include <unistd.h>
#else
#include <process.h>
#endif

namespace raylab {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const fs::path& file, const std::string& reason) {
    throw WriteError("cannot write " + file.string() + ": " + reason);
}

[[noreturn]] void fail(const fs::path& file, std::error_code code) {
    throw WriteError("cannot write " + file.string() + ": " + code.message(), code);
}

std::error_code systemError(int error) { return std::error_code(error, std::generic_category()); }

#ifdef RAYLAB_POSIX_FILES
int currentProcess() { return int(getpid()); }
#else
int currentProcess() { return _getpid(); }
#endif

// ".<name>.tmp-<pid>-<n>" beside the target: hidden, and unique among the writers of this process.
fs::path temporaryName(const fs::path& target) {
    static std::atomic<unsigned> counter{0};
    std::string name(1, '.');
    name += target.filename().string();
    name += ".tmp-";
    name += std::to_string(currentProcess());
    name += '-';
    name += std::to_string(counter++);
    return target.parent_path() / name;
}

#ifdef RAYLAB_POSIX_FILES

// 0, or the errno of the step that failed.
int writeAll(int fd, std::string_view bytes) {
    while (!bytes.empty()) {
        const ssize_t n = ::write(fd, bytes.data(), bytes.size());
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return errno;
        if (n == 0) return EIO;
        bytes.remove_prefix(std::size_t(n));
    }
    return 0;
}

// A device or a pipe cannot be replaced by a file: it is written in place. O_NONBLOCK only for the
// open, so that a pipe nobody reads is refused (ENXIO) instead of blocking forever.
void writeInPlace(const fs::path& file, std::string_view bytes) {
    const int fd = ::open(file.c_str(), O_WRONLY | O_TRUNC | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) fail(file, systemError(errno));
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    int error = writeAll(fd, bytes);
    if (::close(fd) != 0 && error == 0) error = errno;
    if (error != 0) fail(file, systemError(error));
}

// Opens a temporary file of our own (O_EXCL) beside `target`; its name on success.
int openTemporary(const fs::path& target, fs::path& temporary) {
    for (;;) {
        temporary = temporaryName(target);
        const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0 || errno != EEXIST) return fd; // EEXIST: left by a process that had our pid and died
    }
}

void writeReplacing(const fs::path& target, std::string_view bytes) {
    fs::path temporary;
    const int fd = openTemporary(target, temporary);
    if (fd < 0) fail(target, systemError(errno));
    int error = writeAll(fd, bytes);
    // fsync before the rename: after a crash, the name points at the whole new file or the old one.
    if (error == 0 && ::fsync(fd) != 0 && errno != EINVAL) error = errno; // EINVAL: a file system without fsync
    if (::close(fd) != 0 && error == 0) error = errno;
    if (error == 0 && ::rename(temporary.c_str(), target.c_str()) != 0) error = errno;
    if (error != 0) {
        ::unlink(temporary.c_str());
        fail(target, systemError(error));
    }
    // Makes the rename itself durable; the file is whole either way, so a folder that cannot be
    // synced is no error.
    const int folder = ::open(target.parent_path().empty() ? "." : target.parent_path().c_str(), O_RDONLY | O_CLOEXEC);
    if (folder >= 0) {
        ::fsync(folder);
        ::close(folder);
    }
}

#else

void writeInPlace(const fs::path& file, std::string_view bytes) {
    std::ofstream out(file, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    out.close();
    if (!out) fail(file, systemError(errno));
}

void writeReplacing(const fs::path& target, std::string_view bytes) {
    const fs::path temporary = temporaryName(target);
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    out.close();
    std::error_code error;
    if (!out) error = std::error_code(errno, std::generic_category());
    else fs::rename(temporary, target, error);
    if (error) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        fail(target, error);
    }
}

#endif

} // namespace

void writeFileAtomically(const fs::path& file, std::string_view bytes) {
    if (file.empty()) fail(file, "no file name given");
    std::error_code error; // a file not there yet is no error: status() says so
    // Through a symbolic link, to the file it names: the link stays a link.
    fs::path target = file;
    if (fs::is_symlink(fs::symlink_status(file, error))) {
        target = fs::weakly_canonical(file, error);
        if (error) fail(file, error);
    }
    const fs::file_status status = fs::status(target, error);
    if (fs::is_directory(status)) fail(file, "it is a folder");
    if (fs::exists(status) && !fs::is_regular_file(status)) return writeInPlace(target, bytes);
    if (target.has_parent_path()) {
        fs::create_directories(target.parent_path(), error);
        if (error) fail(file, error);
    }
    writeReplacing(target, bytes);
}

std::optional<std::string> readWholeFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return std::nullopt;
    std::string bytes;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) bytes.append(buffer, std::size_t(in.gcount()));
    if (in.bad() || !in.eof()) return std::nullopt;
    return bytes;
}

void copyFileAtomically(const fs::path& from, const fs::path& to) {
    std::error_code error;
    if (!fs::is_regular_file(from, error)) throw std::runtime_error("cannot read " + from.string() + ": not a regular file");
    const std::optional<std::string> bytes = readWholeFile(from);
    if (!bytes) throw std::runtime_error("cannot read " + from.string());
    writeFileAtomically(to, *bytes);
}

} // namespace raylab
