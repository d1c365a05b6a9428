#include "src/file_lock.h"

#include "src/text.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#ifdef _WIN32
#include "src/windows_api.h"
#include <process.h>
#else
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>
#endif

namespace raylab {

namespace fs = std::filesystem;

#ifdef _WIN32

namespace {

// The locked byte lies past the holder's id: a waiting process can still read the id.
constexpr DWORD kLockedOffset = 1u << 20;

bool lockByte(HANDLE handle, DWORD flags) {
    OVERLAPPED at{};
    at.Offset = kLockedOffset;
    return LockFileEx(handle, flags, 0, 1, 0, &at) != 0;
}

} // namespace

FileLock::FileLock(const fs::path& file) : m_file(file) {
    m_handle = CreateFileW(file.wstring().c_str(), GENERIC_READ | GENERIC_WRITE, FILE_SHARE_READ | FILE_SHARE_WRITE, nullptr,
                           OPEN_ALWAYS, FILE_ATTRIBUTE_NORMAL, nullptr);
    if (m_handle == INVALID_HANDLE_VALUE) {
        m_handle = nullptr;
        throw std::runtime_error("cannot open the lock " + printablePath(file) + " (error " + std::to_string(GetLastError()) + ")");
    }
}

FileLock::~FileLock() {
    if (m_handle != nullptr) CloseHandle(static_cast<HANDLE>(m_handle)); // releases the lock
}

bool FileLock::tryAcquire() {
    if (!lockByte(static_cast<HANDLE>(m_handle), LOCKFILE_EXCLUSIVE_LOCK | LOCKFILE_FAIL_IMMEDIATELY)) return false;
    writeHolder();
    return true;
}

bool FileLock::acquire(bool (*)()) {
    if (!lockByte(static_cast<HANDLE>(m_handle), LOCKFILE_EXCLUSIVE_LOCK))
        throw std::runtime_error("cannot take the lock " + printablePath(m_file) + " (error " + std::to_string(GetLastError()) + ")");
    writeHolder();
    return true;
}

void FileLock::writeHolder() {
    const std::string pid = std::to_string(_getpid()) + "\n";
    HANDLE handle = static_cast<HANDLE>(m_handle);
    SetFilePointer(handle, 0, nullptr, FILE_BEGIN);
    DWORD written = 0;
    WriteFile(handle, pid.data(), DWORD(pid.size()), &written, nullptr);
    SetEndOfFile(handle);
}

std::string FileLock::holder() const {
    char text[32] = {};
    DWORD n = 0;
    OVERLAPPED at{};
    ReadFile(static_cast<HANDLE>(m_handle), text, sizeof text - 1, &n, &at);
    std::string pid(text, n);
    pid.erase(pid.find_last_not_of("\r\n ") + 1);
    return pid;
}

int FileLock::descriptor() const { return -1; }

#else

FileLock::FileLock(const fs::path& file) : m_file(file) {
    m_fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (m_fd < 0) throw std::runtime_error("cannot open the lock " + printablePath(file) + ": " + std::strerror(errno));
}

FileLock::~FileLock() {
    if (m_fd >= 0) ::close(m_fd); // releases the lock; the file stays, harmless, for the next holder
}

bool FileLock::tryAcquire() {
    if (::flock(m_fd, LOCK_EX | LOCK_NB) != 0) {
        if (errno != EWOULDBLOCK)
            throw std::runtime_error("cannot take the lock " + printablePath(m_file) + ": " + std::strerror(errno));
        return false;
    }
    writeHolder();
    return true;
}

bool FileLock::acquire(bool (*stop)()) {
    while (::flock(m_fd, LOCK_EX) != 0) {
        if (errno != EINTR)
            throw std::runtime_error("cannot take the lock " + printablePath(m_file) + ": " + std::strerror(errno));
        if (stop != nullptr && stop()) return false;
    }
    writeHolder();
    return true;
}

void FileLock::writeHolder() {
    const std::string pid = std::to_string(getpid()) + "\n";
    if (::ftruncate(m_fd, 0) != 0 || ::pwrite(m_fd, pid.data(), pid.size(), 0) != ssize_t(pid.size()))
        throw std::runtime_error("cannot write the lock " + printablePath(m_file) + ": " + std::strerror(errno));
}

std::string FileLock::holder() const {
    char text[32] = {};
    const ssize_t n = ::pread(m_fd, text, sizeof text - 1, 0);
    std::string pid(text, n > 0 ? std::size_t(n) : 0);
    pid.erase(pid.find_last_not_of("\n ") + 1);
    return pid;
}

int FileLock::descriptor() const { return m_fd; }

#endif

} // namespace raylab
