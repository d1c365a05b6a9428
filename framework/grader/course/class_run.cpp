#include "grader/course/class_run.h"

#include "src/atomic_file.h"
#include "src/csv.h"
#include "src/file_lock.h"
#include "src/messages.h"
#include "src/text.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <system_error>
#include <thread>

#if defined(__unix__) || defined(__APPLE__)
#define RAYLAB_POSIX_CLASS_RUN 1
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>
#endif
#ifdef __linux__
#include <sys/prctl.h>
#endif

namespace raylab::grader {

namespace fs = std::filesystem;

namespace {

constexpr const char* kResultFile = "result.json";
constexpr const char* kLockFile = "grade-class.lock";
constexpr std::size_t kLongestSafeName = 160; // file names stop at 255 bytes

fs::path studentsFolder(const fs::path& out) { return out / "students"; }

// ---- the ledger: a result per student, grades.csv made from them --------------------------------

std::string recordJson(const StudentRecord& record) {
    nlohmann::json cells = nlohmann::json::array();
    for (const auto& [column, value] : record.cells) cells.push_back({{"column", column}, {"value", value}});
    nlohmann::json madeBy = nlohmann::json::array();
    for (const auto& [name, value] : record.madeBy) madeBy.push_back({{"name", name}, {"value", value}});
    const nlohmann::json root{{"student", record.student}, {"cells", cells}, {"made_by", madeBy}};
    // Printable text is UTF-8 already: the handler only guards a hand-made record.
    return root.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

std::optional<StudentRecord> readRecord(const fs::path& studentFolder) {
    std::ifstream in(studentFolder / kResultFile, std::ios::binary);
    if (!in) return std::nullopt;
    try {
        const nlohmann::json root = nlohmann::json::parse(in);
        // The name shown made from the folder's bytes, as at grading: the same for a result written
        // before names were shown as they are now (a raw bidi control), and never made printable twice.
        const std::optional<std::string> folder = studentFolderName(studentFolder.filename().string());
        StudentRecord record{folder ? printableName(*folder) : root.at("student").get<std::string>(), {}};
        for (const nlohmann::json& cell : root.at("cells"))
            record.cells.emplace_back(cell.at("column").get<std::string>(), cell.at("value").get<std::string>());
        if (root.contains("made_by")) // a result written before results said what made them has none
            for (const nlohmann::json& setting : root.at("made_by"))
                record.madeBy.emplace_back(setting.at("name").get<std::string>(), setting.at("value").get<std::string>());
        return record;
    } catch (const nlohmann::json::exception&) {
        return std::nullopt; // never half-written (atomic), so only a hand-edited file: graded again
    }
}

// "timeout 60 (now 180), labs 1 (now all)": the settings of `then` that `now` does not share.
std::string settingsChanged(const Settings& then, const Settings& now) {
    std::string changed;
    const auto valueIn = [](const Settings& settings, const std::string& name) -> std::string {
        for (const auto& [n, v] : settings)
            if (n == name) return v;
        return "?";
    };
    for (const auto& [name, value] : now)
        if (valueIn(then, name) != value)
            changed += (changed.empty() ? "" : "; ") +
                       tr("grade.setting_changed", {{"name", name}, {"then", valueIn(then, name)}, {"now", value}});
    return changed;
}

// The results in OUT, by safe name.
std::map<std::string, StudentRecord> readLedger(const fs::path& out) {
    std::map<std::string, StudentRecord> ledger;
    std::error_code error;
    for (auto it = fs::directory_iterator(studentsFolder(out), error); !error && it != fs::directory_iterator();
         it.increment(error))
        if (auto record = readRecord(it->path())) ledger[it->path().filename().string()] = std::move(*record);
    return ledger;
}

// grades.csv, whole: a row per result, by name; the columns in the order the results give them.
void writeGrades(const fs::path& out, const std::map<std::string, StudentRecord>& ledger) {
    std::vector<const StudentRecord*> rows;
    std::vector<std::string> columns;
    for (const auto& [safe, record] : ledger) {
        rows.push_back(&record);
        for (const auto& cell : record.cells)
            if (std::find(columns.begin(), columns.end(), cell.first) == columns.end()) columns.push_back(cell.first);
    }
    std::sort(rows.begin(), rows.end(), [](const auto* a, const auto* b) { return a->student < b->student; });
    std::vector<std::string> header{"student"};
    header.insert(header.end(), columns.begin(), columns.end());
    std::string csv = csvLine(header);
    for (const StudentRecord* record : rows) {
        std::vector<std::string> line{record->student};
        for (const std::string& column : columns) {
            const auto cell = std::find_if(record->cells.begin(), record->cells.end(),
                                           [&](const auto& c) { return c.first == column; });
            line.push_back(cell != record->cells.end() ? printableText(cell->second) : "");
        }
        csv += csvLine(line);
    }
    writeFileAtomically(out / "grades.csv", csv);
}

// ---- the class folder ---------------------------------------------------------------------------

struct ClassEntries {
    std::vector<StudentWork> students; // by name
    std::vector<std::string> skipped;  // a line each: what was left out and why
};

ClassEntries listClass(const fs::path& classFolder, const fs::path& out) {
    ClassEntries entries;
    std::error_code error;
    const fs::path outCanonical = fs::weakly_canonical(out, error);
    auto it = fs::directory_iterator(classFolder, error);
    if (error) throw std::runtime_error("cannot read the class folder " + printablePath(classFolder) + ": " + error.message());
    for (; !error && it != fs::directory_iterator(); it.increment(error)) {
        const fs::path path = it->path();
        const std::string name = path.filename().string();
        const std::string shown = "skipped '" + printableName(name) + "': ";
        std::error_code entryError;
        const fs::file_status status = fs::symlink_status(path, entryError);
        if (fs::is_symlink(status)) {
            entries.skipped.push_back(shown + "a symbolic link (a submission is a folder of its own)");
        } else if (!fs::is_directory(status)) {
            entries.skipped.push_back(shown + "not a folder");
        } else if (fs::weakly_canonical(path, entryError) == outCanonical) {
            continue; // --out inside the class folder
        } else if (const bool empty = fs::is_empty(path, entryError); entryError) {
            entries.skipped.push_back(shown + "cannot be read (" + entryError.message() + ")");
        } else if (empty) {
            entries.skipped.push_back(shown + "an empty folder");
        } else {
            entries.students.push_back({name, path, studentsFolder(out) / safeStudentName(name)});
        }
    }
    if (error) throw std::runtime_error("cannot read the class folder " + printablePath(classFolder) + ": " + error.message());
    std::sort(entries.students.begin(), entries.students.end(),
              [](const StudentWork& a, const StudentWork& b) { return a.name < b.name; });
    return entries;
}

// ---- stopping: SIGINT and SIGTERM only set a flag; the run stops the student's process itself ----

volatile std::sig_atomic_t g_stopSignal = 0;
int g_stopSignalsDepth = 0; // StopSignals alive: the outermost installs the handlers and restores them
#ifdef RAYLAB_POSIX_CLASS_RUN
struct sigaction g_previousInt {}, g_previousTerm {};
#else
void (*g_previousInt)(int) = nullptr;
void (*g_previousTerm)(int) = nullptr;
#endif

extern "C" void onStopSignal(int signal) { g_stopSignal = signal; }

// ---- one run per OUT ----------------------------------------------------------------------------

// A lock left by a dead run is simply taken (src/file_lock.h).
class RunLock {
public:
    // Takes OUT's lock, or says in `problem` who holds it.
    bool acquire(const fs::path& out, bool wait, std::string& problem) {
        const fs::path file = out / kLockFile;
        try {
            m_lock = std::make_unique<FileLock>(file);
            if (m_lock->tryAcquire()) return true;
            const std::string pid = m_lock->holder();
            const std::string holder = tr("grade.class_lock_held", {{"pid", pid.empty() ? "its pid not written yet" : "pid " + pid},
                                                                    {"out", printablePath(out)},
                                                                    {"lock", printablePath(file)}});
            if (!wait) {
                problem = tr("grade.class_lock_no_wait", {{"holder", holder}});
                return false;
            }
            std::printf("%s\n", tr("grade.class_waiting", {{"holder", holder}}).c_str());
            std::fflush(stdout);
            if (m_lock->acquire([] { return g_stopSignal != 0; })) return true;
            problem = "stopped while waiting for the lock " + printablePath(file);
        } catch (const std::exception& e) {
            problem = e.what();
        }
        return false;
    }
    int descriptor() const { return m_lock ? m_lock->descriptor() : -1; }

private:
    std::unique_ptr<FileLock> m_lock;
};

// ---- grading one student ------------------------------------------------------------------------

enum class Outcome { Graded, Stopped, Failed, DiskFull };

// The exit status of a student's process that stopped on a full disk (sysexits' EX_TEMPFAIL: the
// next run, once there is room, succeeds).
constexpr int kDiskFullStatus = 75;

// Whether runInOwnProcess's status says so.
bool diskFullStatus(int status) {
#ifdef RAYLAB_POSIX_CLASS_RUN
    return WIFEXITED(status) && WEXITSTATUS(status) == kDiskFullStatus;
#else
    return status == kDiskFullStatus;
#endif
}

void gradeAndRecord(const StudentWork& work, const GradeStudent& grade, const Settings& madeBy) {
    StudentRecord record = grade(work);
    record.student = printableName(work.name); // the row's name, whatever the grading called it
    record.madeBy = madeBy;
    writeFileAtomically(work.folder / kResultFile, recordJson(record)); // last: the grading finished
}

#ifdef RAYLAB_POSIX_CLASS_RUN

std::string describeStatus(int status) {
    if (WIFSIGNALED(status)) return "its grading process was killed by signal " + std::to_string(WTERMSIG(status));
    return "its grading process exited with status " + std::to_string(WEXITSTATUS(status));
}

// The run is gone (SIGKILL, SIGHUP, a crash: the kernel sends the student's process SIGTERM) or
// stops it: its whole group goes, the build guard first given a moment to stop its compiler's group.
extern "C" void onRunGone(int) {
    std::signal(SIGTERM, SIG_IGN);
    kill(0, SIGTERM);
    const timespec moment{0, 100'000'000};
    nanosleep(&moment, nullptr);
    kill(0, SIGKILL); // and ourselves
}

// In the student's process, first: it holds none of the run's locks and dies with the run.
void bindToRun(pid_t run, const std::vector<int>& runOnlyDescriptors) {
    setpgid(0, 0);
    for (int fd : runOnlyDescriptors)
        if (fd >= 0) ::close(fd);
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, onRunGone);
#ifdef __linux__
    prctl(PR_SET_PDEATHSIG, SIGTERM);
#endif
    if (getppid() != run) onRunGone(SIGTERM); // the run died before prctl: no signal will come
}

// `work` runs in a process of its own, in its own process group with every build tool it starts
// (the agents die with it), so that a stop ends them all and a crash costs one student. Returns the
// process's wait status, or nothing when it could not start (`why` says so).
std::optional<int> runInOwnProcess(const std::function<void()>& work, const std::vector<int>& runOnlyDescriptors,
                                   std::string& why) {
    std::fflush(nullptr); // or the child would print our buffered lines again
    const pid_t run = getpid();
    const pid_t pid = fork();
    if (pid < 0) {
        why = std::string("cannot start a process: ") + std::strerror(errno);
        return std::nullopt;
    }
    if (pid == 0) {
        bindToRun(run, runOnlyDescriptors);
        int status = 0;
        try {
            work();
        } catch (const std::exception& e) {
            std::fprintf(stderr, "raylab: error: %s\n", printableText(e.what()).c_str());
            status = isDiskFull(e) ? kDiskFullStatus : 1;
        }
        std::fflush(nullptr);
        _exit(status);
    }
    setpgid(pid, pid); // also here, so the group exists before we may signal it
    using Clock = std::chrono::steady_clock;
    Clock::time_point stoppedAt{};
    int status = 0;
    for (;;) {
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (done < 0 && errno != EINTR) {
            why = std::string("lost its grading process: ") + std::strerror(errno);
            return std::nullopt;
        }
        if (g_stopSignal != 0 && stoppedAt == Clock::time_point{}) {
            stoppedAt = Clock::now();
            kill(-pid, SIGTERM);
        } else if (g_stopSignal != 0 && Clock::now() - stoppedAt > std::chrono::seconds(5)) {
            kill(-pid, SIGKILL);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20)); // a signal cuts it short
    }
    kill(-pid, SIGKILL); // whatever of its group is left (its pid is not reused while the group lives)
    return status;
}

Outcome gradeInOwnProcess(const StudentWork& work, const GradeStudent& grade, const Settings& madeBy,
                          const std::vector<int>& runOnlyDescriptors, std::string& why) {
    const std::optional<int> status = runInOwnProcess(
        [&] {
            try {
                gradeAndRecord(work, grade, madeBy);
            } catch (const std::exception& e) {
                if (isDiskFull(e)) throw;
                throw std::runtime_error("grading " + printableName(work.name) + ": " + e.what());
            }
        },
        runOnlyDescriptors, why);
    if (!status) return Outcome::Failed;
    std::error_code error;
    if (fs::exists(work.folder / kResultFile, error)) return Outcome::Graded; // written whole, even if stopped just after
    if (g_stopSignal != 0) return Outcome::Stopped;
    if (diskFullStatus(*status)) return Outcome::DiskFull;
    why = describeStatus(*status);
    return Outcome::Failed;
}

#else

std::optional<int> runInOwnProcess(const std::function<void()>& work, const std::vector<int>&, std::string& why) {
    try {
        work();
        return 0;
    } catch (const std::exception& e) {
        why = e.what();
        return isDiskFull(e) ? kDiskFullStatus : 1;
    }
}

Outcome gradeInOwnProcess(const StudentWork& work, const GradeStudent& grade, const Settings& madeBy, const std::vector<int>&,
                          std::string& why) {
    try {
        gradeAndRecord(work, grade, madeBy);
        return Outcome::Graded;
    } catch (const std::exception& e) {
        why = e.what();
        return g_stopSignal != 0 ? Outcome::Stopped : isDiskFull(e) ? Outcome::DiskFull : Outcome::Failed;
    }
}

#endif

const char* signalName(int signal) { return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "a signal"; }

// Said once, when a disk is full: the run stops, what it graded is kept, and the next run resumes.
int stopOnFullDisk(const fs::path& out) {
    std::printf("%s\n", tr("grade.disk_full_stopped", {{"students", printablePath(studentsFolder(out))}}).c_str());
    std::fflush(stdout);
    return 1;
}

} // namespace

std::string safeStudentName(const std::string& folderName) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string safe;
    for (std::size_t k = 0; k < folderName.size(); ++k) {
        const unsigned char c = static_cast<unsigned char>(folderName[k]);
        const bool kept = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                          (k > 0 && (c == '-' || c == '.'));
        if (kept) {
            safe += char(c);
        } else {
            safe += '%';
            safe += kHex[c >> 4];
            safe += kHex[c & 15];
        }
    }
    if (safe.size() <= kLongestSafeName) return safe;
    std::uint64_t hash = 14695981039346656037ull; // FNV-1a
    for (char c : folderName) hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    std::string cut = safe.substr(0, kLongestSafeName - 17) + "~"; // '~' is never kept: no plain name ends so
    for (int shift = 60; shift >= 0; shift -= 4) cut += kHex[(hash >> shift) & 15];
    return cut;
}

std::optional<std::string> studentFolderName(const std::string& safeName) {
    const auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return -1;
    };
    std::string name;
    for (std::size_t k = 0; k < safeName.size(); ++k) {
        if (safeName[k] != '%') {
            name += safeName[k];
            continue;
        }
        if (k + 2 >= safeName.size() || hex(safeName[k + 1]) < 0 || hex(safeName[k + 2]) < 0) return std::nullopt;
        name += char(hex(safeName[k + 1]) * 16 + hex(safeName[k + 2]));
        k += 2;
    }
    if (name.empty() || safeStudentName(name) != safeName) return std::nullopt; // a cut name, or no safe name
    return name;
}

namespace {

// The ledger's records made with other settings than this run's, taken out of it: those students are
// graded again, and out of the CSV until then.
std::map<std::string, StudentRecord> takeMadeOtherwise(std::map<std::string, StudentRecord>& ledger,
                                                       const Settings& madeBy) {
    std::map<std::string, StudentRecord> madeOtherwise;
    for (auto it = ledger.begin(); it != ledger.end();)
        if (it->second.madeBy != madeBy) {
            madeOtherwise.insert(*it);
            it = ledger.erase(it);
        } else {
            ++it;
        }
    return madeOtherwise;
}

// The run's last lines, and its status: stopped by a signal, students left to grade, or done.
int endOfRun(const fs::path& out, const std::vector<std::string>& unfinished) {
    std::fflush(stdout);
    if (g_stopSignal != 0) {
        std::printf("%s\n", tr("grade.class_stopped", {{"signal", signalName(g_stopSignal)},
                                                        {"grades", printablePath(out / "grades.csv")}}).c_str());
        std::fflush(stdout);
        return 128 + g_stopSignal;
    }
    std::printf("%s\n", tr("grade.class_outputs", {{"grades", printablePath(out / "grades.csv")},
                                                    {"students", printablePath(studentsFolder(out))}}).c_str());
    if (!unfinished.empty()) {
        std::string names;
        for (const std::string& n : unfinished) names += (names.empty() ? "" : ", ") + n;
        std::printf("%s\n", tr("grade.class_unfinished", {{"names", names}}).c_str());
    }
    std::fflush(stdout); // said, even if a signal kills the process on its way out
    return unfinished.empty() ? 0 : 1;
}

} // namespace

StopSignals::StopSignals() {
    if (g_stopSignalsDepth++ > 0) return; // already caught: a signal received so far is kept
    g_stopSignal = 0;
#ifdef RAYLAB_POSIX_CLASS_RUN
    struct sigaction action {};
    action.sa_handler = onStopSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = 0; // no SA_RESTART: a wait for the lock returns at once
    sigaction(SIGINT, &action, &g_previousInt);
    sigaction(SIGTERM, &action, &g_previousTerm);
#else
    g_previousInt = std::signal(SIGINT, onStopSignal);
    g_previousTerm = std::signal(SIGTERM, onStopSignal);
#endif
}

StopSignals::~StopSignals() {
    if (--g_stopSignalsDepth > 0) return;
#ifdef RAYLAB_POSIX_CLASS_RUN
    sigaction(SIGINT, &g_previousInt, nullptr);
    sigaction(SIGTERM, &g_previousTerm, nullptr);
#else
    std::signal(SIGINT, g_previousInt);
    std::signal(SIGTERM, g_previousTerm);
#endif
}

int runClass(const ClassRunOptions& options, const GradeStudent& grade) {
    const fs::path& out = options.out;
    fs::create_directories(studentsFolder(out));
    const StopSignals stopSignals; // before the lock: a wait for it can be interrupted
    RunLock lock;
    std::string problem;
    if (!lock.acquire(out, options.wait, problem)) {
        if (g_stopSignal != 0) return 128 + g_stopSignal;
        std::fprintf(stderr, "raylab: error: %s\n", problem.c_str());
        return 1;
    }
    // A full disk (here, or in a student's process) stops the run: every student after would fail alike.
    try {
        std::map<std::string, StudentRecord> ledger = readLedger(out);
        const std::map<std::string, StudentRecord> madeOtherwise = takeMadeOtherwise(ledger, options.madeBy);
        writeGrades(out, ledger); // the CSV of every finished student, even if a last run stopped before it
        const ClassEntries entries = listClass(options.classFolder, out);
        for (const std::string& line : entries.skipped) std::printf("%s\n", line.c_str());
        std::vector<std::string> unfinished;
        bool prepared = false;
        for (const StudentWork& work : entries.students) {
            if (g_stopSignal != 0) break;
            const std::string shown = printableName(work.name);
            const std::string safe = work.folder.filename().string();
            if (ledger.count(safe)) {
                std::printf("%-20s %s\n", shown.c_str(),
                            tr("grade.class_already_graded", {{"result", printablePath(work.folder / kResultFile)}}).c_str());
                continue;
            }
            if (const auto old = madeOtherwise.find(safe); old != madeOtherwise.end())
                std::printf("%-20s %s\n", shown.c_str(),
                            tr("grade.graded_again", {{"changes", settingsChanged(old->second.madeBy, options.madeBy)}}).c_str());
            std::string why;
            std::vector<int> runOnly = options.runOnlyDescriptors;
            runOnly.push_back(lock.descriptor());
            if (options.beforeFirstStudent && !prepared) { // stopped with the run, as a student's grading
                prepared = true;
                const std::optional<int> status = runInOwnProcess(options.beforeFirstStudent, runOnly, why);
                if (g_stopSignal != 0) break;
                if (status && diskFullStatus(*status)) return stopOnFullDisk(out);
            }
            fs::create_directories(work.folder);
            const Outcome outcome = gradeInOwnProcess(work, grade, options.madeBy, runOnly, why);
            if (outcome == Outcome::Stopped) {
                std::printf("%-20s %s\n", shown.c_str(), tr("grade.class_interrupted").c_str());
                break;
            }
            if (outcome == Outcome::DiskFull) {
                std::printf("%-20s %s\n", shown.c_str(), tr("grade.not_graded_disk_full").c_str());
                return stopOnFullDisk(out);
            }
            std::optional<StudentRecord> record;
            if (outcome == Outcome::Graded) record = readRecord(work.folder);
            if (!record) {
                std::printf("%-20s %s\n", shown.c_str(),
                            tr("grade.class_not_graded", {{"why", why.empty() ? tr("grade.class_no_result") : why}}).c_str());
                unfinished.push_back(shown);
                continue;
            }
            ledger[safe] = std::move(*record);
            writeGrades(out, ledger);
            std::fflush(stdout);
        }
        if (g_stopSignal == 0 && options.afterLastStudent) options.afterLastStudent();
        return endOfRun(out, unfinished);
    } catch (const std::exception& e) {
        if (!isDiskFull(e)) throw;
        std::printf("raylab: %s\n", printableText(e.what()).c_str());
        return stopOnFullDisk(out);
    }
}

std::optional<StudentRecord> readStudentResult(const fs::path& studentFolder) {
    return readRecord(studentFolder);
}

bool isDiskFull(const std::exception& e) {
    std::error_code code;
    if (const auto* write = dynamic_cast<const WriteError*>(&e)) code = write->code();
    else if (const auto* system = dynamic_cast<const std::system_error*>(&e)) code = system->code();
#ifdef EDQUOT
    const bool system = code.category() == std::generic_category() || code.category() == std::system_category();
    if (system && code.value() == EDQUOT) return true;
#endif
    return code == std::errc::no_space_on_device;
}

std::string problemSummary(const std::string& problem) {
    constexpr int kLines = 4;
    constexpr std::size_t kWidth = 200;
    std::istringstream lines(problem);
    std::string summary;
    int count = 0;
    for (std::string line; count < kLines && std::getline(lines, line);) {
        if (line.empty()) continue;
        if (line.size() > kWidth) {
            const std::size_t space = line.rfind(' ', kWidth);
            std::size_t cut = space == std::string::npos || space < kWidth / 2 ? kWidth : space;
            while (cut > 0 && (static_cast<unsigned char>(line[cut]) & 0xC0) == 0x80) --cut; // not inside a UTF-8 character
            line = line.substr(0, cut) + " …";
        }
        summary += (count++ ? "\n" : "") + line;
    }
    return summary;
}

} // namespace raylab::grader
