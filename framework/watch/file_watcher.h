#pragma once
// Waits for a save in the lab folders `raylab watch` follows: inotify on Linux (a save is seen at
// once, nothing is read in between), elsewhere, or when RAYLAB_WATCH_POLL is set, the files' times
// looked at every few hundred milliseconds (standard C++: Windows, macOS).

#include <chrono>
#include <filesystem>
#include <memory>
#include <vector>

namespace raylab::watch {

class FileWatcher {
public:
    // `folders`: watched with everything under them; only the lab's files count (isWatchedFile): a
    // file of a hidden folder, an editor's temporary or backup file, a handout or a picture is ignored.
    explicit FileWatcher(std::vector<std::filesystem::path> folders);
    ~FileWatcher();
    FileWatcher(const FileWatcher&) = delete;
    FileWatcher& operator=(const FileWatcher&) = delete;

    // The files saved since the last call, waiting up to `timeout` for the first; empty when none was.
    std::vector<std::filesystem::path> changes(std::chrono::milliseconds timeout);

    // "inotify" or "polling": what this watcher uses, for the console's line.
    const char* how() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

// Whether a change of `file` is a change of the code: a plain name (letters, digits, '_', '-', '.',
// not hidden) ending in .cpp, .cc, .h, .hpp or .toml; never an editor's temporary or backup file.
bool isWatchedFile(const std::filesystem::path& file);

} // namespace raylab::watch
