#include "grader/sandbox/compile_stage.h"

#include "grader/sandbox/sandbox_internal.h"

#ifdef RAYLAB_POSIX_SANDBOX

#include "grader/sandbox/unprivileged.h"

#include <algorithm>
#include <stdexcept>
#include <sys/stat.h>

namespace raylab::grader::detail {

namespace fs = std::filesystem;

namespace {

bool isWithin(const fs::path& path, const fs::path& folder) {
    const fs::path relative = path.lexically_relative(folder);
    return !relative.empty() && *relative.begin() != "..";
}

// The system's folders, which the user reads where they are (and Landlock allows as they are).
bool isSystemFolder(const fs::path& folder) {
    if (isWithin(folder, "/usr")) return true;
    return std::any_of(std::begin(kSystemTopFolders), std::end(kSystemTopFolders),
                       [&](const char* top) { return isWithin(folder, top); });
}

fs::path spelled(const fs::path& path) { return fs::absolute(path).lexically_normal(); }

// A folder of the stage's (made when missing) that others may enter but not list.
void makeEnterable(const fs::path& folder) {
    if (fs::create_directory(folder) && chmod(folder.c_str(), 0711) != 0)
        throw std::runtime_error("grader: cannot make the folder " + folder.string());
}

} // namespace

CompileStage::CompileStage(const std::vector<fs::path>& folders, const UnprivilegedUser& user) {
    // /tmp itself, not TMPDIR: every user may enter it, whatever the grader's own temporary folder.
    m_root = makeEnterableFolder("/tmp/raylab-compile-XXXXXX");
    m_view = m_root / "view";
    m_output = m_root / "out";
    fs::create_directory(m_output);
    if (!handOver(m_output, user))
        throw std::runtime_error("grader: cannot hand the compiler its folder " + m_output.string());
    std::vector<fs::path> copied;
    for (const fs::path& folder : folders) {
        std::error_code missing;
        if (isSystemFolder(spelled(folder))) m_readable.push_back(spelled(folder));
        else if (fs::is_directory(folder, missing)) copied.push_back(spelled(folder));
    }
    std::sort(copied.begin(), copied.end()); // a folder before the folders inside it
    for (const fs::path& folder : copied) {
        const auto inside = [&](const fs::path& outer) { return isWithin(folder, outer); };
        if (std::any_of(m_copied.begin(), m_copied.end(), inside)) continue; // copied with its parent
        // The copy's parents, entered and not listed, as the stage's own folder.
        fs::path parent = m_view;
        makeEnterable(parent);
        for (const fs::path& part : folder.relative_path().parent_path()) makeEnterable(parent /= part);
        const fs::path copy = m_view / folder.relative_path();
        copyReadOnly(fs::canonical(folder), copy); // the folder a link (a submission's, course/submission.cpp) names
        m_copied.push_back(folder);
        m_readable.push_back(copy);
    }
}

CompileStage::~CompileStage() {
    std::error_code ignored;
    fs::remove_all(m_root, ignored);
}

std::optional<fs::path> CompileStage::copyOf(const fs::path& path) const {
    const fs::path place = spelled(path);
    for (const fs::path& folder : m_copied)
        if (place == folder || isWithin(place, folder)) return m_view / place.relative_path();
    return std::nullopt;
}

std::string CompileStage::original(std::string text) const {
    const std::string view = m_view.string();
    for (std::size_t at = text.find(view); at != std::string::npos; at = text.find(view, at)) {
        if (at + view.size() < text.size() && text[at + view.size()] == '/') text.erase(at, view.size());
        else at += view.size();
    }
    return text;
}

std::string CompileStage::originalPart(std::string_view chunk, bool last) {
    std::string text = original(m_pending.append(chunk));
    // A copy's path is put back once it is followed by '/': the last bytes may begin one.
    const std::size_t keep = last ? 0 : std::min(text.size(), m_view.string().size());
    m_pending = text.substr(text.size() - keep);
    text.resize(text.size() - keep);
    return text;
}

} // namespace raylab::grader::detail

#endif
