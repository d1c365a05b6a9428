// The fallback's user: who it is, the folders it is given, and the child becoming it for good.
#include "grader/sandbox/sandbox_internal.h"

#ifdef RAYLAB_POSIX_SANDBOX

#include "grader/sandbox/unprivileged.h"

#include <grp.h>
#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

namespace raylab::grader::detail {

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
