#pragma once
// A lock that one process holds at a time, on a file, released by the system when its holder exits or
// dies (flock on POSIX, LockFileEx on Windows): a lock left by a killed process is simply taken. Its
// holder writes its process id in the file, so that who waits can say for whom.

#include <filesystem>
#include <string>

namespace raylab {

class FileLock {
public:
    // Opens (makes) `file`; throws std::runtime_error naming it when it cannot.
    explicit FileLock(const std::filesystem::path& file);
    ~FileLock(); // releases it
    FileLock(const FileLock&) = delete;
    FileLock& operator=(const FileLock&) = delete;

    // Takes the lock if no other process holds it; false when one does.
    bool tryAcquire();
    // Waits until the lock is free and takes it; false when a signal interrupted the wait and
    // `stop()` says to give up.
    bool acquire(bool (*stop)() = nullptr);
    // The process id its holder wrote ("" when none is written yet).
    std::string holder() const;
    // The lock's descriptor (POSIX; -1 elsewhere): a child that must not hold it closes it.
    int descriptor() const;

private:
    void writeHolder();
    std::filesystem::path m_file;
#ifdef _WIN32
    void* m_handle = nullptr;
#else
    int m_fd = -1;
#endif
};

} // namespace raylab
