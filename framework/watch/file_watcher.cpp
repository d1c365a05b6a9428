#include "watch/file_watcher.h"

#include <algorithm>
#include <cctype>
#include <iterator>
#include <string_view>
#include <cstdlib>
#include <map>
#include <thread>

#ifdef __linux__
#include <poll.h>
#include <sys/inotify.h>
#include <unistd.h>
#endif

namespace raylab::watch {

namespace fs = std::filesystem;

namespace {

bool isHidden(const fs::path& p) { return p.filename().string().starts_with("."); }

// Every watched file and its time, for the polling watcher.
std::map<fs::path, fs::file_time_type> snapshot(const std::vector<fs::path>& folders) {
    std::map<fs::path, fs::file_time_type> times;
    std::error_code error;
    for (const fs::path& folder : folders)
        for (auto entry = fs::recursive_directory_iterator(folder, error); !error && entry != fs::recursive_directory_iterator();
             entry.increment(error)) {
            if (isHidden(entry->path())) {
                if (entry->is_directory(error)) entry.disable_recursion_pending();
                continue;
            }
            if (entry->is_regular_file(error) && isWatchedFile(entry->path()))
                times[entry->path()] = entry->last_write_time(error);
        }
    return times;
}

} // namespace

bool isWatchedFile(const fs::path& file) {
    // A lab file's name is plain (letters, digits, '_', '-', '.'; not hidden) and ends as code or a
    // TOML file does. Editors' and tools' own files are not: sed -i's sedXXXXXX, vim's .x.swp and its
    // 4913 probe, x~, emacs's #x# and .#x, x.tmp, x.orig, x.rej, x.bak, kate's x.kate-swp...
    static constexpr std::string_view kExtensions[] = {".cpp", ".cc", ".h", ".hpp", ".toml"};
    const std::string name = file.filename().string();
    if (name.empty() || name.starts_with(".")) return false;
    for (const char c : name)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.')) return false;
    const std::string extension = file.extension().string();
    return extension != name && std::find(std::begin(kExtensions), std::end(kExtensions), extension) != std::end(kExtensions);
}

struct FileWatcher::Impl {
    std::vector<fs::path> folders;
    std::map<fs::path, fs::file_time_type> times; // polling
#ifdef __linux__
    int inotify = -1;
    std::map<int, fs::path> watched; // watch descriptor -> folder

    // Watches `folder` and the folders under it; the files already there are added to `found` (a
    // folder made after the watcher started may be filled before its watch is added).
    void watchTree(const fs::path& folder, std::vector<fs::path>& found) {
        constexpr std::uint32_t kEvents = IN_CLOSE_WRITE | IN_MOVED_TO | IN_CREATE | IN_DELETE;
        const int wd = inotify_add_watch(inotify, folder.c_str(), kEvents);
        if (wd >= 0) watched[wd] = folder;
        std::error_code error;
        for (const fs::directory_entry& entry : fs::directory_iterator(folder, error)) {
            if (isHidden(entry.path()) || entry.is_symlink(error)) continue;
            if (entry.is_directory(error)) watchTree(entry.path(), found);
            else if (isWatchedFile(entry.path())) found.push_back(entry.path());
        }
    }

    std::vector<fs::path> inotifyChanges(std::chrono::milliseconds timeout) {
        std::vector<fs::path> changed;
        pollfd waiting{inotify, POLLIN, 0};
        if (poll(&waiting, 1, int(timeout.count())) <= 0) return changed;
        alignas(inotify_event) char buffer[16384];
        const ssize_t n = read(inotify, buffer, sizeof buffer);
        for (ssize_t at = 0; at < n;) {
            const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
            at += ssize_t(sizeof(inotify_event) + event->len);
            const auto folder = watched.find(event->wd);
            if (folder == watched.end() || event->len == 0) continue;
            const fs::path file = folder->second / event->name;
            if (event->mask & IN_ISDIR) {
                if (event->mask & (IN_CREATE | IN_MOVED_TO) && !isHidden(file)) watchTree(file, changed);
                continue;
            }
            if (event->mask & IN_CREATE) continue; // its IN_CLOSE_WRITE follows
            // A file written and then renamed over a lab file (sed -i, many editors) is gone: the
            // rename is the save; a file deleted is a change.
            std::error_code error;
            if (isWatchedFile(file) && (event->mask & IN_DELETE || fs::exists(file, error))) changed.push_back(file);
        }
        std::sort(changed.begin(), changed.end());
        changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
        return changed;
    }
#endif

    std::vector<fs::path> pollingChanges(std::chrono::milliseconds timeout) {
        const auto until = std::chrono::steady_clock::now() + timeout;
        for (;;) {
            auto now = snapshot(folders);
            std::vector<fs::path> changed;
            for (const auto& [file, time] : now)
                if (const auto before = times.find(file); before == times.end() || before->second != time) changed.push_back(file);
            for (const auto& [file, time] : times)
                if (!now.contains(file)) changed.push_back(file);
            times = std::move(now);
            if (!changed.empty() || std::chrono::steady_clock::now() >= until) return changed;
            std::this_thread::sleep_for(std::min<std::chrono::milliseconds>(std::chrono::milliseconds(250), timeout));
        }
    }
};

FileWatcher::FileWatcher(std::vector<fs::path> folders) : m_impl(std::make_unique<Impl>()) {
    m_impl->folders = std::move(folders);
#ifdef __linux__
    if (std::getenv("RAYLAB_WATCH_POLL") == nullptr) m_impl->inotify = inotify_init1(IN_CLOEXEC | IN_NONBLOCK);
    if (m_impl->inotify >= 0) {
        std::vector<fs::path> present;
        for (const fs::path& folder : m_impl->folders) m_impl->watchTree(folder, present);
        return;
    }
#endif
    m_impl->times = snapshot(m_impl->folders);
}

FileWatcher::~FileWatcher() {
#ifdef __linux__
    if (m_impl->inotify >= 0) close(m_impl->inotify);
#endif
}

std::vector<fs::path> FileWatcher::changes(std::chrono::milliseconds timeout) {
#ifdef __linux__
    if (m_impl->inotify >= 0) return m_impl->inotifyChanges(timeout);
#endif
    return m_impl->pollingChanges(timeout);
}

const char* FileWatcher::how() const {
#ifdef __linux__
    if (m_impl->inotify >= 0) return "inotify";
#endif
    return "polling";
}

} // namespace raylab::watch
