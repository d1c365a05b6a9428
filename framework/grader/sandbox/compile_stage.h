#pragma once
// What the fallback's compiler reads, copied where its unprivileged user can read it (confined_compile.h).
// Without namespaces that user walks the real paths: a tree under /root or a home folder of mode 0700
// is closed to it, and so is a build folder there. So the guard copies the folders the compiler is
// allowed (the submission, the stubs, the include folders; the system's stay where they are) into
// /tmp/raylab-compile-XXXXXX/view/<their own path>, root's, read-only, entered but not listed, gives the
// compiler those copies' paths and a folder of its own there for its outputs, and puts the original
// paths back in what it says and in its dependency file. Nothing else of the tree is copied: no
// solution, no reference, no other student's file. POSIX only.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace raylab::grader::detail {

struct UnprivilegedUser;

class CompileStage {
public:
    // Copies each of `folders` outside the system's (/usr, /lib*, /bin, /sbin); a missing one, or one
    // inside another, is left out. Throws when the stage cannot be made.
    CompileStage(const std::vector<std::filesystem::path>& folders, const UnprivilegedUser& user);
    ~CompileStage(); // removes the stage
    CompileStage(const CompileStage&) = delete;
    CompileStage& operator=(const CompileStage&) = delete;

    // `path` (absolute, or relative to the current folder) as the compiler reaches it: its copy's path
    // when it lies in a copied folder, else nothing.
    std::optional<std::filesystem::path> copyOf(const std::filesystem::path& path) const;

    // The folders the compiler reads: the copies, and the system's folders as they are.
    const std::vector<std::filesystem::path>& readable() const { return m_readable; }

    // The compiler's own folder (its outputs, its temporary files), handed to the user.
    const std::filesystem::path& output() const { return m_output; }

    // `text` with each copy's path put back to the original's.
    std::string original(std::string text) const;

    // The same on a stream (the compiler's error output): what can be passed on of `chunk`, a path
    // cut at its end kept for the next; `last` gives the rest.
    std::string originalPart(std::string_view chunk, bool last = false);

private:
    std::filesystem::path m_root, m_view, m_output;
    std::vector<std::filesystem::path> m_copied, m_readable;
    std::string m_pending; // originalPart's unfinished end
};

} // namespace raylab::grader::detail
