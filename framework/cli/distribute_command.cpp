// raylab distribute: writes the tree students receive: everything but the reference solutions and
// what would give them away, by where it lives (answerFolder below). It builds, runs and self-grades
// on its own: the labs' descriptions (labs/<lab>/lab.toml: items and points) and the grader's
// references (each lab's framework/grader/labs/<lab>/references/) go with it, and the reference of
// each lab the course gives (left out, the framework calls its functions) in framework/given/<lab>/.
// tests/grading/distribute_ships_no_solution.cpp checks what it writes.
#include "build_info.h"
#include "commands.h"

#include "grader/lab_catalog.h"
#include "src/atomic_file.h"
#include "src/messages.h"
#include "src/text.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace raylab::cli {

namespace {

namespace fs = std::filesystem;

grader::LabCatalog courseCatalog(const fs::path& source) {
    return grader::loadLabCatalog(source / "labs");
}

// What a students' tree leaves out follows from where a file lives, never from a list of files
// (docs/instructors.md, "The student distribution"): a folder named `solutions` (the answers: the
// labs' references, a toy lab's), a folder named `instructors` (what holds or is made from an answer,
// built only where solutions/ is: studies that write a lab's formulas out, the tests that need them,
// the valid variants and bad submissions, patches against the solutions), a grading folder's
// `mistakes/` (patches too; its references/mistakes/, the signatures self-grading names, ships), and the
// labs the course leaves out (labFoldersWithheld). Nor is what is not the project's: git's folder, the
// builds and what they write.
bool answerFolder(const fs::path& relative) {
    const std::vector<fs::path> parts(relative.begin(), relative.end());
    if (std::any_of(parts.begin(), parts.end(), [](const fs::path& part) { return part == "solutions" || part == "instructors"; }))
        return true;
    return parts.size() >= 5 && parts[0] == "framework" && parts[1] == "grader" && parts[2] == "labs" &&
           parts[4] == "mistakes";
}

bool workspaceProduct(const fs::path& relative) {
    const std::string top = relative.begin()->string();
    return top == ".git" || top == ".cache" || top == "out" || top == "compile_commands.json" || top.rfind("build", 0) == 0;
}

// The pictures under docs/ that the handouts of `lab` (labs/<lab>/*.md) show, Markdown's ![...](...)
// or HTML's <img src="...">, as paths from the top of the tree.
void handoutPictures(const fs::path& source, const std::string& lab, std::set<std::string>& pictures) {
    // Bounded spans: libstdc++'s regex recurses once a character, and a `[` that no `]` follows for
    // pages (an escape sequence quoted in docs/grading.md) overflowed the stack under ASan.
    static const std::regex picture(R"re(!\[[^\]]{0,400}\]\(([^)\s#]+)|<img[^>]{0,400}\ssrc="([^"]+)")re");
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(source / lab, error)) {
        if (entry.path().extension() != ".md") continue;
        const std::optional<std::string> text = readWholeFile(entry.path());
        if (!text) continue;
        for (std::sregex_iterator it(text->begin(), text->end(), picture), end; it != end; ++it) {
            const std::string target = (*it)[1].matched ? (*it)[1].str() : (*it)[2].str();
            const std::string path = (fs::path(lab) / target).lexically_normal().generic_string();
            if (path.rfind("docs/", 0) == 0) pictures.insert(path);
        }
    }
}

bool registersByName(const std::string& gradingFile) {
    static const std::set<std::string> parts = {"shadings.cpp", "shapes.cpp", "lights.cpp", "figure_steps.cpp"};
    return parts.count(gradingFile) != 0;
}

// Of the labs the course's list (course.toml) leaves out, their folders in labs/ (their figures with
// them) and their grading folders, and the pictures of docs/ that only their handouts show: absent,
// not a zero. A given lab keeps, of its grading folder, what registers it by name (its shadings, kinds
// of objects and lights, and figure steps: cmake/RaylabLabs.cmake's raylab_lab_shadings).
std::set<std::string> labFoldersWithheld(const fs::path& source, const grader::LabCatalog& course) {
    std::set<std::string> folders, absentPictures, coursePictures;
    for (const auto& entry : fs::directory_iterator(source / "labs")) {
        const std::string id = entry.path().filename().string();
        const std::string grading = "framework/grader/labs/" + id;
        if (!entry.is_directory()) continue;
        if (course.labOfId(id) != nullptr) {
            handoutPictures(source, "labs/" + id, coursePictures);
            continue;
        }
        folders.insert("labs/" + id);
        handoutPictures(source, "labs/" + id, absentPictures);
        const bool given = std::any_of(course.given.begin(), course.given.end(),
                                       [&](const grader::LabDescription& l) { return l.id == id; });
        if (!given) {
            folders.insert(grading);
            continue;
        }
        std::error_code error;
        for (const auto& part : fs::directory_iterator(source / grading, error)) {
            const std::string name = part.path().filename().string();
            if (!registersByName(name)) folders.insert(grading + "/" + name);
        }
    }
    for (const std::string& picture : absentPictures) // a picture a handed-out lab shows too stays
        if (!coursePictures.count(picture)) folders.insert(picture);
    return folders;
}

bool withheld(const fs::path& relative, const std::set<std::string>& labFolders) {
    return answerFolder(relative) || workspaceProduct(relative) || labFolders.count(relative.generic_string()) != 0;
}

// framework/given/<lab>/ of each given lab: its reference (solutions/<lab>/), its own headers
// (labs/<lab>/*.h) and its lab.toml (the kinds of objects and lights it brings), which CMake compiles
// and reads where the students' tree has no solutions/.
void addGivenLabs(const fs::path& source, const grader::LabCatalog& course, std::vector<TreeFile>& files) {
    for (const grader::LabDescription& lab : course.given) {
        std::error_code error;
        if (!fs::exists(source / "solutions" / lab.id, error) && fs::is_directory(source / "framework/given" / lab.id, error))
            continue; // a students' tree: its framework/given/ is copied as it is
        const auto add = [&](const fs::path& folder, const std::string& extension) {
            std::size_t added = 0;
            for (const auto& entry : fs::directory_iterator(folder, error))
                if (entry.is_regular_file() && entry.path().extension() == extension) {
                    files.push_back({fs::path("framework/given") / lab.id / entry.path().filename(), entry.path()});
                    ++added;
                }
            return added;
        };
        if (add(source / "solutions" / lab.id, ".cpp") == 0)
            throw std::runtime_error(tr("distribute.no_given_reference", {{"lab", std::to_string(lab.number)},
                                                                          {"folder", (source / "solutions" / lab.id).string()}}));
        add(source / "labs" / lab.id, ".h");
        files.push_back({fs::path("framework/given") / lab.id / "lab.toml", source / "labs" / lab.id / "lab.toml"});
    }
}

// framework/stubs/<lab>/ of each lab of the course: its code as handed out (labs/<lab>/*.cpp and its
// headers), which CMake builds into the command-line tool in place of a lab whose code does not compile,
// and into each lab's own grading program in place of the labs it does not use (cmake/RaylabLabs.cmake).
void addStubs(const fs::path& source, const grader::LabCatalog& course, std::vector<TreeFile>& files) {
    std::error_code error;
    if (fs::is_directory(source / "framework/stubs", error)) return; // a students' tree: copied as it is
    for (const grader::LabDescription& lab : course.labs)
        for (const auto& entry : fs::directory_iterator(source / "labs" / lab.id, error))
            if (entry.is_regular_file() && (entry.path().extension() == ".cpp" || entry.path().extension() == ".h"))
                files.push_back({fs::path("framework/stubs") / lab.id / entry.path().filename(), entry.path()});
}

// A Markdown file of the students' tree without what leads to a lab the course leaves out: a table
// row that links there is dropped, another link is made its text alone (a handout's "next: lab 4" in
// a course of labs 1 to 3) and a picture from there is dropped. Links elsewhere, web addresses and
// anchors are kept.
std::string withoutLinksToAbsentLabs(const std::string& text, const fs::path& relative, const std::set<std::string>& labFolders) {
    static const std::regex link(R"((!?)\[([^\]]{0,400})\]\(([^)\s#]*)([^)\s]*)\))"); // bounded: handoutPictures
    const auto intoAbsentLab = [&](const std::string& target) {
        if (target.empty() || target.find("://") != std::string::npos) return false;
        const std::string path = (relative.parent_path() / target).lexically_normal().generic_string();
        return std::any_of(labFolders.begin(), labFolders.end(), [&](const std::string& folder) {
            return (folder.rfind("labs/", 0) == 0 || folder.rfind("docs/", 0) == 0) &&
                   (path == folder || path.rfind(folder + "/", 0) == 0);
        });
    };
    const auto linksIntoAbsentLab = [&](const std::string& line) {
        for (std::sregex_iterator it(line.begin(), line.end(), link), end; it != end; ++it)
            if (intoAbsentLab((*it)[3].str())) return true;
        return false;
    };
    std::string kept; // the table rows first, line by line; then the links, which may span lines
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
        if (line.rfind('|', 0) != 0 || !linksIntoAbsentLab(line)) kept += line + (lines.eof() ? "" : "\n");
    std::string out;
    auto last = kept.cbegin();
    for (std::sregex_iterator it(kept.begin(), kept.end(), link), end; it != end; ++it) {
        const std::smatch& m = *it;
        out.append(last, m[0].first);
        out += !intoAbsentLab(m[3].str()) ? m[0].str() : m[1].length() ? std::string() : m[2].str();
        last = m[0].second;
    }
    return out.append(last, kept.cend());
}

std::string fileText(const fs::path& file) {
    std::optional<std::string> text = readWholeFile(file);
    if (!text) throw std::runtime_error("cannot read " + printablePath(file));
    return std::move(*text);
}

} // namespace

namespace {

// What a students' tree is made from: the source (absolute), its course, and what it withholds.
struct TreeSource {
    fs::path source;
    grader::LabCatalog course;
    std::set<std::string> withheld;

    explicit TreeSource(const fs::path& tree)
        : source(fs::canonical(tree)), course(courseCatalog(source)), withheld(labFoldersWithheld(source, course)) {}
};

std::vector<TreeFile> treeFiles(const TreeSource& tree) {
    std::vector<TreeFile> files;
    for (auto it = fs::recursive_directory_iterator(tree.source); it != fs::recursive_directory_iterator(); ++it) {
        const fs::path relative = it->path().lexically_relative(tree.source); // fs::relative would follow links
        if (withheld(relative, tree.withheld) || it->is_symlink()) {
            if (it->is_directory()) it.disable_recursion_pending();
            continue;
        }
        if (it->is_regular_file()) files.push_back({relative, it->path()});
    }
    addGivenLabs(tree.source, tree.course, files);
    addStubs(tree.source, tree.course, files);
    return files;
}

} // namespace

std::vector<TreeFile> studentTreeFiles(const fs::path& source) { return treeFiles(TreeSource(source)); }

int writeStudentTree(const fs::path& source, const fs::path& out) {
    std::error_code error;
    if (fs::exists(out, error) && !fs::is_empty(out, error))
        throw std::invalid_argument(out.string() + " exists and is not empty; choose a new folder");
    const TreeSource tree(source);
    const std::vector<TreeFile> files = treeFiles(tree); // before `out` exists: never inside it
    for (const TreeFile& file : files) {
        fs::create_directories((out / file.relative).parent_path());
        if (file.relative.extension() == ".md")
            writeFileAtomically(out / file.relative, withoutLinksToAbsentLabs(fileText(file.source), file.relative, tree.withheld));
        else
            fs::copy_file(file.source, out / file.relative, fs::copy_options::overwrite_existing); // its permissions too
    }
    writeStudentsReadme(out, tree.course);
    const bool hadReadme = std::any_of(files.begin(), files.end(), [](const TreeFile& f) { return f.relative == "README.md"; });
    return int(files.size()) + (hadReadme ? 1 : 2); // LISEZMOI.md, and README.md where there was none
}

namespace {

int distribute(const fs::path& source, const fs::path& out) {
    const int files = writeStudentTree(source, out);
    std::printf("%s\n", tr("distribute.written", {{"files", std::to_string(files)},
                                                   {"folder", out.string()},
                                                   {"build", kStudentsBuildCommand}})
                            .c_str());
    const grader::LabCatalog course = courseCatalog(fs::canonical(source));
    std::string given;
    for (const grader::LabDescription& lab : course.given) given += (given.empty() ? "" : ", ") + std::to_string(lab.number);
    if (!given.empty())
        std::printf("%s\n", tr("distribute.given", {{"count", std::to_string(course.given.size())},
                                                     {"labs", given},
                                                     {"folder", out.string()}})
                                .c_str());
    return 0;
}

} // namespace

void addDistributeCommand(CLI::App& app, Context& context) {
    auto out = std::make_shared<std::string>();
    CLI::App* command =
        app.add_subcommand("distribute", tr("cli.distribute"));
    command->add_option(tr("cli.type.DIR"), *out, tr("cli.new_folder"))->required();
    command->callback([&context, out] { context.exitStatus = distribute(build::kSourceDir, *out); });
}

} // namespace raylab::cli
