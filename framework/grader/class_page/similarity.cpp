#include "grader/class_page/similarity.h"

#include "grader/sandbox/install_command.h"
#include "grader/sandbox/process.h"
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

std::optional<std::string> readText(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return std::nullopt;
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// The stub's lines of a lab, trimmed: what every student was given, never evidence of anything.
std::set<std::string> stubLinesOf(const LabDescription& lab, const fs::path& labsFolder) {
    std::set<std::string> lines;
    for (const std::string& name : lab.files())
        if (const std::optional<std::string> text = readText(labsFolder / lab.id / name)) {
            std::istringstream in(*text);
            for (std::string line; std::getline(in, line);)
                if (!trimmed(line).empty()) lines.insert(trimmed(line));
        }
    return lines;
}

// A student's lab files joined (a comment line naming each), the lines that are the stub's marked;
// nothing when they wrote no line of their own.
struct JoinedCode {
    std::string shown, compared; // compared: the stub's lines left empty, so both keep their line numbers
    std::vector<bool> stub;
};

std::optional<JoinedCode> joinedCode(const LabDescription& lab, const fs::path& copy, const std::set<std::string>& stubLines) {
    JoinedCode code;
    bool own = false;
    for (const std::string& name : lab.files()) {
        const std::optional<std::string> text = readText(copy / lab.id / name);
        if (!text) continue;
        code.shown += "// " + name + "\n";
        code.compared += "\n";
        code.stub.push_back(true);
        std::istringstream in(printableText(*text));
        for (std::string line; std::getline(in, line);) {
            const bool given = trimmed(line).empty() || stubLines.count(trimmed(line)) > 0;
            own = own || !given;
            code.shown += line + "\n";
            code.compared += (given ? "" : line) + "\n";
            code.stub.push_back(given);
        }
    }
    if (!own) return std::nullopt;
    return code;
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
    std::optional<std::string> text = readText(output);
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

// One lab: every pair's overlap, the class's usual overlap, the pairs most alike with their runs.
std::optional<LabSimilarity> compareLab(const fs::path& sim, const ClassResults& results, const LabDescription& lab,
                                        const fs::path& labsFolder, const fs::path& folder, std::string& why) {
    LabSimilarity similarity;
    similarity.lab = lab.number;
    fs::remove_all(folder);
    fs::create_directories(folder);
    const std::set<std::string> stubLines = stubLinesOf(lab, labsFolder);
    std::vector<std::string> files;
    for (const ClassMember& m : results.students)
        if (std::optional<JoinedCode> code = joinedCode(lab, m.place / "submission", stubLines)) {
            const std::size_t k = similarity.students.size();
            std::ofstream(folder / fileName(k), std::ios::binary) << code->compared;
            files.push_back(fileName(k));
            similarity.students.push_back(m.student);
            similarity.texts.push_back(std::move(code->shown));
            similarity.stubLines.push_back(std::move(code->stub));
        }
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
