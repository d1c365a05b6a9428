#include "grader/class_page/similarity.h"

#include "grader/sandbox/install_command.h"
#include "grader/sandbox/process.h"
#include "src/atomic_file.h"
#include "src/messages.h"
#include "src/text.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

namespace raylab::grader {

namespace fs = std::filesystem;

namespace {

constexpr const char* kSimProgram = "sim_c++";
constexpr double kSimSeconds = 300.; // a class of hundreds of students takes seconds: past this, something is wrong

std::string trimmed(const std::string& line) {
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) return "";
    return line.substr(first, line.find_last_not_of(" \t\r") - first + 1);
}

// The stub's lines of a lab, trimmed: what every student was given, never evidence of anything.
std::set<std::string> stubLinesOf(const LabDescription& lab, const fs::path& labsFolder) {
    std::set<std::string> lines;
    for (const std::string& name : lab.files())
        if (const std::optional<std::string> text = readWholeFile(labsFolder / lab.id / name)) {
            std::istringstream in(*text);
            for (std::string line; std::getline(in, line);)
                if (!trimmed(line).empty()) lines.insert(trimmed(line));
        }
    return lines;
}

// A student's lab files joined, a comment line naming each; a line is given when it is blank or the
// stub's.
struct JoinedCode {
    std::string student;
    std::vector<std::string> lines;
    std::vector<bool> given;
};

std::optional<JoinedCode> joinedCode(const LabDescription& lab, const fs::path& copy, const std::set<std::string>& stubLines) {
    JoinedCode code;
    for (const std::string& name : lab.files()) {
        const std::optional<std::string> text = readWholeFile(copy / lab.id / name);
        if (!text) continue;
        code.lines.push_back("// " + name);
        code.given.push_back(true);
        std::istringstream in(printableText(*text));
        for (std::string line; std::getline(in, line);) {
            code.lines.push_back(line);
            code.given.push_back(trimmed(line).empty() || stubLines.count(trimmed(line)) > 0);
        }
    }
    if (code.lines.empty()) return std::nullopt;
    return code;
}

// The lines more than a quarter of the class wrote alike (and at least three students), as MOSS
// ignores a passage found in many programs: the handout's formula, the way everyone writes a loop.
// Two students who share them share what the class shares; what is left is their own.
std::set<std::string> commonLines(const std::vector<JoinedCode>& codes) {
    std::map<std::string, std::size_t> writers;
    for (const JoinedCode& code : codes) {
        std::set<std::string> own;
        for (std::size_t k = 0; k < code.lines.size(); ++k)
            if (!code.given[k]) own.insert(trimmed(code.lines[k]));
        for (const std::string& line : own) ++writers[line];
    }
    const std::size_t most = std::max<std::size_t>(2, codes.size() / 4);
    std::set<std::string> common;
    for (const auto& [line, count] : writers)
        if (count > most) common.insert(line);
    return common;
}

// sim_c++ with `arguments` in `folder` (the files named relative to it); its output, or nothing
// (`why` says what went wrong).
std::optional<std::string> runSim(const fs::path& sim, const fs::path& folder, const std::vector<std::string>& arguments,
                                  std::string& why) {
    const fs::path output = folder / "sim-output.txt";
    fs::remove(output);
    std::vector<std::string> argv{sim.string(), "-T", "-o", output.filename().string()};
    argv.insert(argv.end(), arguments.begin(), arguments.end());
    ProcessOptions options;
    options.workingDirectory = folder;
    options.timeLimit = kSimSeconds;
    options.output = folder / "sim-errors.txt";
    const ProcessResult result = runProcess(argv, options);
    std::optional<std::string> text = readWholeFile(output);
    if (!result.succeeded() || !text) {
        why = tr("class_page.sim_failed", {{"program", sim.string()}, {"folder", printablePath(folder)}});
        return std::nullopt;
    }
    return text;
}

std::string fileName(std::size_t student) { return std::to_string(student) + ".cpp"; }

// "3.cpp consists for 87 % of 5.cpp material": 87 for (3, 5).
std::map<std::pair<std::size_t, std::size_t>, int> percentages(const std::string& output) {
    static const std::regex line(R"((\d+)\.cpp consists for (\d+) % of (\d+)\.cpp material)");
    std::map<std::pair<std::size_t, std::size_t>, int> found;
    for (auto it = std::sregex_iterator(output.begin(), output.end(), line); it != std::sregex_iterator(); ++it)
        found[{std::stoul((*it)[1]), std::stoul((*it)[3])}] = std::stoi((*it)[2]);
    return found;
}

// "0.cpp: line 8-46 |1.cpp: line 9-47 [310]": the runs two files share.
std::vector<MatchedRun> matchedRuns(const std::string& output) {
    static const std::regex line(R"((\d+)\.cpp: line (\d+)-(\d+)\s*\|\s*(\d+)\.cpp: line (\d+)-(\d+)\s*\[(\d+)\])");
    std::vector<MatchedRun> runs;
    for (auto it = std::sregex_iterator(output.begin(), output.end(), line); it != std::sregex_iterator(); ++it)
        runs.push_back({std::stoi((*it)[2]), std::stoi((*it)[3]), std::stoi((*it)[5]), std::stoi((*it)[6]), std::stoi((*it)[7])});
    return runs;
}

double quantile(std::vector<int> values, double q) {
    if (values.empty()) return 0.;
    std::sort(values.begin(), values.end());
    const double at = q * double(values.size() - 1);
    const std::size_t below = std::size_t(at);
    const double above = below + 1 < values.size() ? values[below + 1] : values[below];
    return values[below] + (at - double(below)) * (above - values[below]);
}

// The students of the class with code of their own in `lab`, into `similarity` (their names and
// texts) and `folder` (the files sim_c++ compares, <k>.cpp); returns those files' names.
std::vector<std::string> writeOwnCode(const ClassResults& results, const LabDescription& lab, const fs::path& labsFolder,
                                      const fs::path& folder, LabSimilarity& similarity) {
    const std::set<std::string> stubLines = stubLinesOf(lab, labsFolder);
    std::vector<JoinedCode> codes;
    for (const ClassMember& m : results.students)
        if (std::optional<JoinedCode> code = joinedCode(lab, m.place / "submission", stubLines)) {
            code->student = m.student;
            codes.push_back(std::move(*code));
        }
    const std::set<std::string> common = commonLines(codes);
    std::vector<std::string> files;
    for (const JoinedCode& code : codes) {
        // Compared: the student's own lines; the others left empty, so that line numbers stay the shown ones.
        std::string shown, compared;
        std::vector<bool> grey;
        bool own = false;
        for (std::size_t k = 0; k < code.lines.size(); ++k) {
            const bool theirs = !code.given[k] && !common.count(trimmed(code.lines[k]));
            own = own || theirs;
            shown += code.lines[k] + "\n";
            compared += (theirs ? code.lines[k] : "") + "\n";
            grey.push_back(!theirs);
        }
        if (!own) continue; // nothing but the stub and what most of the class wrote
        const std::size_t k = similarity.students.size();
        std::ofstream(folder / fileName(k), std::ios::binary) << compared;
        files.push_back(fileName(k));
        similarity.students.push_back(code.student);
        similarity.texts.push_back(std::move(shown));
        similarity.leftOut.push_back(std::move(grey));
    }
    return files;
}

// One lab: every pair's overlap, the class's usual overlap, the pairs most alike with their runs.
std::optional<LabSimilarity> compareLab(const fs::path& sim, const ClassResults& results, const LabDescription& lab,
                                        const fs::path& labsFolder, const fs::path& folder, std::string& why) {
    LabSimilarity similarity;
    similarity.lab = lab.number;
    fs::remove_all(folder);
    fs::create_directories(folder);
    const std::vector<std::string> files = writeOwnCode(results, lab, labsFolder, folder, similarity);
    const std::size_t n = similarity.students.size();
    if (n < 2) return similarity;
    std::vector<std::string> arguments{"-p", "-e", "-a", "-t", "1"};
    arguments.insert(arguments.end(), files.begin(), files.end());
    const std::optional<std::string> output = runSim(sim, folder, arguments, why);
    if (!output) return std::nullopt;
    const auto percent = percentages(*output);
    std::vector<SimilarPair> pairs;
    std::vector<int> overlaps;
    for (std::size_t a = 0; a < n; ++a)
        for (std::size_t b = a + 1; b < n; ++b) {
            const auto find = [&](std::size_t x, std::size_t y) {
                const auto it = percent.find({x, y});
                return it == percent.end() ? 0 : it->second;
            };
            pairs.push_back({a, b, std::max(find(a, b), find(b, a)), false, {}});
            overlaps.push_back(pairs.back().overlap);
        }
    similarity.comparedPairs = pairs.size();
    similarity.median = quantile(overlaps, 0.5);
    const double q1 = quantile(overlaps, 0.25), q3 = quantile(overlaps, 0.75);
    similarity.fence = q3 + 1.5 * (q3 - q1);
    std::stable_sort(pairs.begin(), pairs.end(), [](const SimilarPair& x, const SimilarPair& y) { return x.overlap > y.overlap; });
    std::erase_if(pairs, [](const SimilarPair& pair) { return pair.overlap == 0; }); // nothing alike to show
    pairs.resize(std::min(pairs.size(), kShownPairs));
    for (SimilarPair& pair : pairs) {
        pair.unusual = pair.overlap > similarity.fence;
        const std::optional<std::string> runs = runSim(sim, folder, {"-n", "-e", "-s", fileName(pair.first), fileName(pair.second)}, why);
        if (!runs) return std::nullopt;
        pair.runs = matchedRuns(*runs);
    }
    similarity.pairs = std::move(pairs);
    return similarity;
}

} // namespace

SimilarityReport findSimilarSubmissions(const ClassResults& results, const LabCatalog& labs, const fs::path& labsFolder,
                                        const fs::path& scratch) {
    SimilarityReport report;
    const fs::path sim = findProgram(kSimProgram);
    if (sim.empty()) {
        report.note = tr("class_page.sim_missing",
                         {{"program", kSimProgram}, {"install", installCommand("similarity-tester", "", "")}});
        return report;
    }
    for (const LabDescription& lab : labs.labs) {
        std::string why;
        std::optional<LabSimilarity> similarity =
            compareLab(sim, results, lab, labsFolder, scratch / ("lab" + std::to_string(lab.number)), why);
        if (!similarity) {
            report.note = why;
            return report;
        }
        report.labs.push_back(std::move(*similarity));
    }
    return report;
}

} // namespace raylab::grader
