// Which sandbox confines a student's program here: RAYLAB_SANDBOX when it says, else the best there is.
#include "grader/sandbox/sandbox_internal.h"

#ifdef RAYLAB_POSIX_SANDBOX

#include "grader/sandbox/unprivileged.h"

#include <cstdlib>
#include <string_view>
#include <unistd.h>

namespace raylab::grader::detail {

SandboxMode sandboxMode(bool allowed) {
    const char* asked = std::getenv("RAYLAB_SANDBOX");
    const std::string_view mode = asked ? asked : "";
    if (!allowed || mode == "none") return SandboxMode::processGroup;
    if (mode != "fallback" && !bubblewrap().empty()) return SandboxMode::bubblewrap;
    // Only root can become another user; anyone else is left with the process group.
    return unprivilegedUser() ? SandboxMode::unprivileged : SandboxMode::processGroup;
}

} // namespace raylab::grader::detail

#endif
