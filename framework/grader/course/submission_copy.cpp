#include "grader/course/submission_copy.h"

#include "src/atomic_file.h"
#include "src/messages.h"
#include "src/text.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <map>
#include <set>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#ifndef _WIN32
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#else
#include <fstream>
#include <iterator>
#endif

namespace raylab::grader {

namespace fs = std::filesystem;

namespace {

// A lab file is a page or two of code: anything larger is not one, and must not fill the grader's memory.
constexpr std::uintmax_t kMaxFileBytes = 1 << 20;
// A whole repository is a few thousand entries, 6 folders deep: a submission made to exhaust the walk
// stops here.
constexpr int kMaxDepth = 12;
constexpr int kMaxEntries = 50000;
// The grade lists this many ignored files, then how many more.
constexpr std::size_t kMaxListed = 12;

std::string labFileNames(const LabCatalog& catalog) {
    std::string files;
    for (const LabDescription& lab : catalog.labs)
        for (const std::string& name : lab.files()) files += (files.empty() ? "" : ", ") + name;
    return files;
}

bool sourceLike(const fs::path& file) {
    const std::string extension = file.extension().string();
    for (const char* source : {".cpp", ".cc", ".cxx", ".c", ".h", ".hpp", ".hh", ".hxx", ".ipp", ".inl", ".tpp"})
        if (extension == source) return true;
    return false;
}

// How well a file's folder says which lab it is for: its lab's id, a name whose first number is the
// lab's (tp3, "Lab 3", lab3-final), or anything else (the files flat, a wrapping folder).
int folderRank(const std::string& folder, const LabDescription& lab) {
    if (folder == lab.id) return 0;
    const auto digit = std::find_if(folder.begin(), folder.end(), [](char c) { return c >= '0' && c <= '9'; });
    const auto end = std::find_if(digit, folder.end(), [](char c) { return c < '0' || c > '9'; });
    return digit != folder.end() && std::string(digit, end) == std::to_string(lab.number) ? 1 : 2;
}

struct Candidate {
    fs::path relative; // in the submission
    const LabDescription* lab = nullptr;
    std::string name;  // its declared name
    int rank = 2;
    int depth = 0;

    auto order() const { return std::tie(rank, depth, relative); }
};

// Reads a regular file that has no other name, without following a link nor blocking on a pipe;
// nullopt with the reason otherwise. The submission is not the grader's: each check is on the file
// that was opened, not on its name.
std::optional<std::string> readLabFile(const fs::path& file, std::string& why) {
#ifndef _WIN32
    const int fd = ::open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        why = errno == ELOOP ? tr("submission.link") : tr("submission.unreadable", {{"why", std::strerror(errno)}});
        return std::nullopt;
    }
    struct stat info {};
    std::optional<std::string> bytes;
    if (::fstat(fd, &info) != 0) why = tr("submission.unreadable", {{"why", std::strerror(errno)}});
    else if (!S_ISREG(info.st_mode)) why = tr("submission.not_regular");
    else if (info.st_nlink != 1) why = tr("submission.hard_link");
    else if (std::uintmax_t(info.st_size) > kMaxFileBytes) why = tr("submission.too_big", {{"bytes", std::to_string(kMaxFileBytes)}});
    else {
        bytes.emplace();
        char buffer[65536];
        for (ssize_t got; (got = ::read(fd, buffer, sizeof buffer)) != 0;) {
            if (got < 0 && errno == EINTR) continue;
            if (got < 0 || bytes->size() + std::size_t(got) > kMaxFileBytes) { // it grew, or failed, while read
                why = got < 0 ? tr("submission.unreadable", {{"why", std::strerror(errno)}})
                              : tr("submission.too_big", {{"bytes", std::to_string(kMaxFileBytes)}});
                bytes.reset();
                break;
            }
            bytes->append(buffer, std::size_t(got));
        }
    }
    ::close(fd);
    return bytes;
#else
    std::error_code error;
    if (!fs::is_regular_file(fs::symlink_status(file, error)) || fs::hard_link_count(file, error) != 1 ||
        fs::file_size(file, error) > kMaxFileBytes) {
        why = tr("submission.not_regular");
        return std::nullopt;
    }
    std::ifstream in(file, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in && !in.eof()) {
        why = tr("submission.unreadable", {{"why", "read error"}});
        return std::nullopt;
    }
    return bytes;
#endif
}

// Every lab file of a submission, and what it holds that is not one, without following anything.
class Walk {
public:
    explicit Walk(const LabCatalog& catalog) {
        for (const LabDescription& lab : catalog.labs) {
            for (const std::string& name : lab.files()) m_owner[name] = &lab;
            // What the course ships beside the lab files (a lab's own header): no student's file to leave
            // out, and none to say so of. A students' tree keeps its lab folders as handed out in
            // framework/stubs/ (raylab distribute); elsewhere labs/ is as handed out.
            const fs::path labs = lab.file.parent_path();
            std::error_code error;
            fs::path handedOut = labs.parent_path().parent_path() / "framework" / "stubs" / lab.id;
            if (!fs::is_directory(handedOut, error)) handedOut = labs;
            for (fs::directory_iterator it(handedOut, error), end; !error && it != end; it.increment(error))
                m_shipped.insert(it->path().filename().string());
        }
    }

    void folder(const fs::path& root, const fs::path& relative, int depth) {
        std::error_code error;
        std::vector<fs::directory_entry> entries;
        for (fs::directory_iterator it(root / relative, error), end; !error && it != end; it.increment(error))
            entries.push_back(*it);
        if (error) ignore(relative, tr("submission.unreadable", {{"why", error.message()}}));
        std::sort(entries.begin(), entries.end()); // the same choice whatever order the folder lists
        for (const fs::directory_entry& entry : entries) {
            if (++m_entries > kMaxEntries) return;
            const std::string name = entry.path().filename().string();
            if (name.empty() || name[0] == '.' || name == "__MACOSX") continue; // hidden files, archivers' additions
            visit(root, relative / entry.path().filename(), depth, entry.symlink_status(error).type());
        }
    }

    std::vector<Candidate> candidates;
    std::vector<std::string> ignored;

    void ignore(const fs::path& relative, const std::string& why) {
        ignored.push_back(tr("submission.ignored_file", {{"file", printablePath(relative)}, {"why", why}}));
    }

private:
    void visit(const fs::path& root, const fs::path& relative, int depth, fs::file_type type) {
        if (type == fs::file_type::directory) {
            if (depth < kMaxDepth) folder(root, relative, depth + 1);
            return;
        }
        if (type == fs::file_type::symlink) return ignore(relative, tr("submission.link"));
        if (type != fs::file_type::regular) return ignore(relative, tr("submission.not_regular"));
        const auto owner = m_owner.find(relative.filename().string());
        if (owner == m_owner.end()) {
            if (sourceLike(relative) && !m_shipped.count(relative.filename().string())) ignore(relative, tr("submission.not_lab_file"));
            return;
        }
        const std::string parent = relative.has_parent_path() ? relative.parent_path().filename().string() : "";
        candidates.push_back({relative, owner->second, owner->first, folderRank(parent, *owner->second), depth});
    }

    std::map<std::string, const LabDescription*> m_owner;
    std::set<std::string> m_shipped;
    int m_entries = 0;
};

} // namespace

SubmissionCopy copySubmission(const fs::path& submission, const LabCatalog& catalog, const fs::path& destination) {
    SubmissionCopy copy;
    copy.folder = destination;
    fs::remove_all(destination); // a link there is removed, not followed
    fs::create_directories(destination);
    Walk walk(catalog);
    // "labs/" would have lstat follow the link it names: the folder is asked without its last slash.
    const fs::path top = submission.has_filename() ? submission : submission.parent_path();
    std::error_code error;
    const fs::file_status status = fs::symlink_status(top, error);
    if (fs::is_symlink(status)) walk.ignore(top.filename(), tr("submission.link"));
    else if (!fs::is_directory(status)) walk.ignore(top.filename(), tr("submission.not_regular"));
    else walk.folder(top, {}, 0);

    // Per declared file, the best place it was found; the others are listed unless they hold the same.
    std::map<std::string, std::vector<Candidate>> byName;
    for (Candidate& c : walk.candidates) byName[c.name].push_back(std::move(c));
    for (auto& [name, found] : byName) {
        std::sort(found.begin(), found.end(), [](const Candidate& a, const Candidate& b) { return a.order() < b.order(); });
        std::optional<std::string> kept;
        fs::path keptFrom;
        for (const Candidate& c : found) {
            std::string why;
            std::optional<std::string> bytes = readLabFile(top / c.relative, why);
            if (!bytes) walk.ignore(c.relative, why);
            else if (!kept) {
                writeFileAtomically(destination / c.lab->id / c.name, *bytes);
                kept = std::move(bytes);
                keptFrom = c.relative;
                if (std::find(copy.labs.begin(), copy.labs.end(), c.lab->number) == copy.labs.end())
                    copy.labs.push_back(c.lab->number);
            } else if (*bytes != *kept) {
                walk.ignore(c.relative, tr("submission.other_copy", {{"file", printablePath(keptFrom)}}));
            }
        }
    }
    std::sort(copy.labs.begin(), copy.labs.end());
    copy.ignored = std::move(walk.ignored);
    return copy;
}

std::string noLabFileMessage(const LabCatalog& catalog) {
    std::string folders;
    for (const LabDescription& lab : catalog.labs) folders += (folders.empty() ? "" : ", ") + lab.id + "/";
    return tr("submission.no_lab_file", {{"files", labFileNames(catalog)}, {"folders", folders}});
}

std::string ignoredFilesNote(const SubmissionCopy& copy, const LabCatalog& catalog) {
    if (copy.ignored.empty()) return "";
    std::string note =
        tr("submission.ignored", {{"count", std::to_string(copy.ignored.size())}, {"files", labFileNames(catalog)}});
    for (std::size_t k = 0; k < copy.ignored.size() && k < kMaxListed; ++k) note += "\n  " + copy.ignored[k];
    if (copy.ignored.size() > kMaxListed)
        note += "\n  " + tr("submission.ignored_more", {{"count", std::to_string(copy.ignored.size() - kMaxListed)}});
    return note;
}

GradeResult gradeWithoutLabFiles(const GradeSetup& setup, const SubmissionCopy& copy) {
    const std::string why = noLabFileMessage(setup.labs);
    GradeResult result = gradeBuildFailure(setup, "");
    for (CheckOutcome& c : result.checks) c.message = why;
    for (FigureOutcome& f : result.figures) f.reason = why;
    result.problems = {why};
    if (const std::string note = ignoredFilesNote(copy, setup.labs); !note.empty()) result.problems.push_back(note);
    return result;
}

} // namespace raylab::grader
