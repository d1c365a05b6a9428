#include "grader/course/run_scratch.h"

#include <cerrno>
#include <cstring>
#include <random>
#include <stdexcept>

#if defined(__unix__) || defined(__APPLE__)
#define RAYLAB_POSIX_SCRATCH 1
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

namespace raylab::grader {

namespace fs = std::filesystem;

namespace {

// The file a run locks in its scratch folder: a folder without it is no run's (a test's, a
// user's), and is never removed.
constexpr const char* kRunMark = ".raylab-run";

std::string prefix(const std::string& what) { return "raylab-" + what + "-"; }

#ifdef RAYLAB_POSIX_SCRATCH

// The run's mark in `folder`, opened without following a link, when it is a regular file of ours; -1 otherwise.
int openMark(const fs::path& folder) {
    const int fd = ::open((folder / kRunMark).c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) return -1;
    struct stat status {};
    if (::fstat(fd, &status) != 0 || !S_ISREG(status.st_mode) || status.st_uid != ::geteuid()) {
        ::close(fd);
        return -1;
    }
    return fd;
}

#endif

} // namespace

std::vector<fs::path> removeAbandonedScratch(const fs::path& folder, const std::string& what) {
    std::vector<fs::path> removed;
#ifdef RAYLAB_POSIX_SCRATCH
    std::error_code error;
    std::vector<fs::path> candidates;
    for (auto it = fs::directory_iterator(folder, error); !error && it != fs::directory_iterator(); it.increment(error))
        if (it->path().filename().string().rfind(prefix(what), 0) == 0 && !it->is_symlink()) candidates.push_back(it->path());
    for (const fs::path& candidate : candidates) {
        const int fd = openMark(candidate);
        if (fd < 0) continue;
        if (::flock(fd, LOCK_EX | LOCK_NB) == 0) { // no live run holds it
            std::error_code ignored;
            fs::remove_all(candidate, ignored);
            if (!fs::exists(candidate, ignored)) removed.push_back(candidate);
        }
        ::close(fd);
    }
#else
    (void)folder;
    (void)what;
#endif
    return removed;
}

RunScratch::RunScratch(const std::string& what) {
    const fs::path temporary = fs::temp_directory_path();
    m_removed = removeAbandonedScratch(temporary, what);
#ifdef RAYLAB_POSIX_SCRATCH
    std::string folder = (temporary / (prefix(what) + "XXXXXX")).string();
    if (::mkdtemp(folder.data()) == nullptr)
        throw std::runtime_error("cannot make a scratch folder in " + temporary.string() + ": " + std::strerror(errno));
    m_path = folder;
    // The mark is locked under another name, then renamed: a sweep never sees it unlocked.
    const fs::path pending = m_path / ".raylab-run-pending";
    m_descriptor = ::open(pending.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (m_descriptor < 0 || ::flock(m_descriptor, LOCK_EX) != 0 || ::rename(pending.c_str(), (m_path / kRunMark).c_str()) != 0) {
        const std::string why = std::strerror(errno);
        std::error_code ignored;
        fs::remove_all(m_path, ignored);
        if (m_descriptor >= 0) ::close(m_descriptor);
        throw std::runtime_error("cannot lock the scratch folder " + m_path.string() + ": " + why);
    }
#else
    m_path = temporary / (prefix(what) + std::to_string(std::random_device{}()));
    fs::create_directories(m_path);
#endif
}

RunScratch::~RunScratch() {
    std::error_code ignored;
    fs::remove_all(m_path, ignored);
#ifdef RAYLAB_POSIX_SCRATCH
    if (m_descriptor >= 0) ::close(m_descriptor);
#endif
}

} // namespace raylab::grader
