#include "grader/sandbox/confined_compile.h"

#include "grader/sandbox/build_limits.h"
#include "grader/sandbox/sandbox_internal.h"
#include "grader/sandbox/scratch_file.h"
#include "grader/sandbox/unprivileged.h"

#include <cstdlib>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

namespace raylab::grader {

namespace fs = std::filesystem;

namespace {

bool isWithinAny(const fs::path& path, const std::vector<fs::path>& folders) {
    for (const fs::path& folder : folders) {
        const fs::path relative = path.lexically_relative(folder);
        if (!relative.empty() && *relative.begin() != "..") return true;
    }
    return false;
}

// A folder of its own beside `object`, made with mkdtemp: no other compile shares it.
fs::path makePrivateFolder(const fs::path& object) {
    std::string pattern = (object.parent_path() / ".raylab-guard-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) return {};
    return pattern;
}

// The fallback's command: each word that names an allowed file or folder (a source, `-I<folder>`, an
// include folder after -isystem) names its copy. The target a dependency file names (-MT, -MQ) stays.
void renameAllowedPaths(std::vector<std::string>& command, const detail::CompileStage& stage) {
    for (std::size_t i = 1; i < command.size(); ++i) {
        std::string& word = command[i];
        if (word == "-MT" || word == "-MQ") {
            ++i;
        } else if (word.rfind("-I", 0) == 0 && word.size() > 2) {
            if (const auto copy = stage.copyOf(word.substr(2))) word = "-I" + copy->string();
        } else if (!word.empty() && word.front() != '-') {
            std::error_code error;
            if (fs::path(word).is_absolute() || fs::exists(word, error))
                if (const auto copy = stage.copyOf(word)) word = copy->string();
        }
    }
}

} // namespace

ConfinedCompile::ConfinedCompile(const fs::path& bwrap, const std::vector<std::string>& compiler,
                                 const std::vector<fs::path>& readable, const detail::UnprivilegedUser* user) {
    std::vector<std::string> command = compiler;
    std::vector<fs::path> bound;
    // The fallback: the compiler reads copies, and writes in the stage (the build folder may be closed to it).
    if (bwrap.empty() && user) {
        m_stage.emplace(readable, *user);
        m_private = m_stage->output();
        m_handedOver = true;
        renameAllowedPaths(command, *m_stage);
    }
    for (std::size_t i = 0; i + 1 < command.size(); ++i) {
        if (command[i] != "-o" && command[i] != "-MF") continue;
        const fs::path place = fs::absolute(compiler[i + 1]);
        if (m_private.empty()) m_private = makePrivateFolder(place);
        if (m_private.empty()) break; // no private folder: the outputs stay unwritable, the compile fails
        const fs::path file = m_private / (std::to_string(m_outputs.size()) + "-" + place.filename().string());
        m_outputs.push_back({file, place, command[i] == "-MF"});
        command[i + 1] = file.string();
    }
    // Not handed over: the compiler cannot write there, and the compile fails.
    if (user && !m_private.empty() && !m_stage) m_handedOver = detail::handOver(m_private, *user);
    std::vector<fs::path> folders, programs;
    if (m_stage) folders = m_stage->readable();
    else
        for (const fs::path& folder : readable) folders.push_back(fs::absolute(folder));
    // The programs of the command (a launcher, the compiler) when they live outside /usr.
    for (const std::string& word : compiler) {
        std::error_code error;
        const fs::path program(word);
        if (program.is_absolute() && !isWithinAny(program, {"/usr"}) && fs::is_regular_file(program, error) &&
            access(program.c_str(), X_OK) == 0)
            programs.push_back(program);
    }
    m_rules = detail::systemRules();
    m_rules.read.insert(m_rules.read.end(), folders.begin(), folders.end());
    m_rules.execute.insert(m_rules.execute.end(), programs.begin(), programs.end());
    if (!m_private.empty()) m_rules.readWrite.push_back(m_private);
    if (bwrap.empty()) {
        m_command = command;
        return;
    }
    m_command = detail::bubblewrapSystem(bwrap);
    const auto bind = [&](const char* how, const fs::path& path) {
        m_command.insert(m_command.end(), {how, path.string(), path.string()});
        bound.push_back(path);
    };
    for (const fs::path& folder : folders) bind("--ro-bind-try", folder);
    for (const fs::path& program : programs) bind("--ro-bind", program);
    if (!m_private.empty()) bind("--bind", m_private);
    // The compile's own folder: its relative paths (a -MT target) are read from there; empty inside.
    const fs::path cwd = fs::current_path();
    if (!isWithinAny(cwd, bound)) m_command.insert(m_command.end(), {"--dir", cwd.string()});
    // ccache, when it is the launcher, compiles without its cache: the cache holds other builds' objects.
    m_command.insert(m_command.end(), {"--setenv", "CCACHE_DISABLE", "1", "--chdir", cwd.string(), "--"});
    m_command.insert(m_command.end(), command.begin(), command.end());
}

ConfinedCompile::~ConfinedCompile() {
    std::error_code ignored;
    if (!m_private.empty()) fs::remove_all(m_private, ignored);
}

bool ConfinedCompile::deliver() const {
    for (const Output& output : m_outputs) {
        std::error_code error;
        if (m_stage) { // in /tmp, often another file system: read back as a file the user wrote, written whole
            const ScratchFile written = readScratchFile(output.file, kCompilerFileBytes);
            if (!written.found || written.refused || written.cut) return false;
            const fs::path next = output.place.string() + ".raylab-next";
            std::ofstream out(next, std::ios::binary | std::ios::trunc);
            out << (output.dependencies ? m_stage->original(written.text) : written.text);
            out.close();
            if (!out) return false;
            fs::rename(next, output.place, error);
        } else {
            fs::rename(output.file, output.place, error);
        }
        if (error) return false;
        // Written by the fallback's user: root's again, so that a process it left cannot rewrite it.
        const char* place = output.place.c_str();
        if (m_handedOver && (chown(place, getuid(), getgid()) != 0 || chmod(place, 0644) != 0)) return false;
    }
    return true;
}

} // namespace raylab::grader
