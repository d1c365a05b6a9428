// The fallback's user: who it is, the folders it is given, and the child becoming it for good.
#include "grader/sandbox/sandbox_internal.h"

#ifdef RAYLAB_POSIX_SANDBOX

#include "grader/sandbox/unprivileged.h"

#include <grp.h>
#include <pwd.h>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

namespace raylab::grader::detail {

namespace fs = std::filesystem;

namespace {

// Readable and, for a program, runnable by anyone; never writable (root keeps them).
void makeReadOnly(const fs::path& path, bool program) {
    const mode_t mode = fs::is_directory(path) || program ? 0555 : 0444;
    if (chown(path.c_str(), 0, 0) != 0 || chmod(path.c_str(), mode) != 0)
        throw std::runtime_error("grader: cannot hand the unprivileged user its copy " + path.string());
}

// A path as a JSON string writes it (quotes and backslashes escaped).
std::string jsonText(const fs::path& path) {
    std::string text;
    for (const char ch : path.string()) {
        if (ch == '"' || ch == '\\') text += '\\';
        text += ch;
    }
    return text;
}

} // namespace

fs::path makeEnterableFolder(const fs::path& pattern) {
    std::string name = pattern.string();
    if (mkdtemp(name.data()) == nullptr || chmod(name.c_str(), 0711) != 0)
        throw std::runtime_error("grader: cannot make the folder " + name);
    return name;
}

void copyReadOnly(const fs::path& from, const fs::path& to) {
    const fs::file_status status = fs::symlink_status(from);
    if (fs::is_regular_file(status)) {
        fs::copy_file(from, to);
        makeReadOnly(to, false);
        return;
    }
    if (!fs::is_directory(status)) return;
    fs::create_directory(to);
    makeReadOnly(to, false); // root still writes into it
    // The iterator follows no link to a folder; a link to a file is seen as a link and left out.
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(from)) {
        const fs::path copy = to / entry.path().lexically_relative(from);
        if (entry.is_symlink()) continue;
        if (entry.is_directory()) fs::create_directory(copy);
        else if (entry.is_regular_file()) fs::copy_file(entry.path(), copy);
        else continue;
        makeReadOnly(copy, false);
    }
}

AgentStage::AgentStage(const fs::path& program, const std::vector<fs::path>& readable) : m_given(readable) {
    // /tmp, which every user may enter, whatever the tree's folders; a folder of each run's own, removed
    // with it (a folder shared by a process's runs would stay behind one that ends with _exit, as each
    // student of a class run does).
    m_folder = makeEnterableFolder("/tmp/raylab-agent-XXXXXX");
    m_program = m_folder / program.filename();
    fs::copy_file(program, m_program);
    makeReadOnly(m_program, true);
    for (std::size_t k = 0; k < readable.size(); ++k) {
        const fs::path place = m_folder / ("input" + std::to_string(k));
        fs::create_directory(place);
        makeReadOnly(place, false);
        const fs::path copy = place / readable[k].filename();
        std::error_code missing;
        if (fs::exists(readable[k], missing)) copyReadOnly(readable[k], copy);
        m_readable.push_back(copy);
    }
}

AgentStage::~AgentStage() {
    std::error_code ignored;
    fs::remove_all(m_folder, ignored);
}

std::string AgentStage::renamed(std::string requests) const {
    for (std::size_t k = 0; k < m_given.size(); ++k) {
        const std::string from = '"' + jsonText(m_given[k]), to = '"' + jsonText(m_readable[k]);
        for (std::size_t at = requests.find(from); at != std::string::npos; at = requests.find(from, at)) {
            const char next = at + from.size() < requests.size() ? requests[at + from.size()] : '\0';
            if (next == '"' || next == '/') {
                requests.replace(at, from.size(), to);
                at += to.size();
            } else {
                at += from.size();
            }
        }
    }
    return requests;
}

const std::optional<UnprivilegedUser>& unprivilegedUser() {
    static const std::optional<UnprivilegedUser> found = []() -> std::optional<UnprivilegedUser> {
        if (geteuid() != 0) return std::nullopt;
        for (const char* name : {"raylab-grader", "nobody"}) {
            const passwd* entry = getpwnam(name);
            if (entry && entry->pw_uid != 0 && entry->pw_gid != 0)
                return UnprivilegedUser{entry->pw_uid, entry->pw_gid, name};
        }
        return std::nullopt;
    }();
    return found;
}

bool handOver(const std::filesystem::path& folder, const UnprivilegedUser& user) {
    return chown(folder.c_str(), user.uid, user.gid) == 0 && chmod(folder.c_str(), 0700) == 0;
}

bool dropPrivileges(const UnprivilegedUser& user) {
    if (setgroups(0, nullptr) != 0 || setgid(user.gid) != 0 || setuid(user.uid) != 0) return false;
    // As root, setuid sets the saved user too: root is gone only if it cannot be taken back.
    return setuid(0) != 0 && geteuid() == user.uid && getegid() == user.gid;
}

} // namespace raylab::grader::detail

#endif
