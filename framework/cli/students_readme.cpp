// The students' tree's own README.md (English) and LISEZMOI.md (French), written by `raylab
// distribute` and `raylab autograder github` over the instructors' README: what the tree holds, the
// one command that builds it, and the commands of a lab. The labs come from their lab.toml.
#include "commands.h"

#include "grader/lab_catalog.h"
#include "src/atomic_file.h"
#include "src/messages.h"

#include <filesystem>
#include <string>
#include <utility>

namespace raylab::cli {

namespace {

namespace fs = std::filesystem;

// The lab's handout in `language`, else its English one, else its folder: a path of the tree.
std::string handout(const fs::path& tree, const grader::LabDescription& lab, Language language) {
    const std::string folder = "labs/" + lab.id + "/";
    if (language == Language::Fr && fs::is_regular_file(tree / folder / "README.fr.md")) return folder + "README.fr.md";
    if (fs::is_regular_file(tree / folder / "README.md")) return folder + "README.md";
    return folder;
}

std::string readme(const fs::path& tree, const grader::LabCatalog& labs, Language language) {
    const auto say = [language](const char* id, MessageArgs args = {}) {
        return tr(language, id, std::move(args)) + "\n\n"; // a paragraph
    };
    std::string text =
        say("distribute.readme_title") + say("distribute.readme_intro") + tr(language, "distribute.readme_labs") + "\n";
    for (const grader::LabDescription& lab : labs.labs) {
        std::string files;
        for (const std::string& file : lab.files()) files += (files.empty() ? "" : ", ") + ("`" + file + "`");
        text += tr(language, "distribute.readme_lab_row",
                   {{"lab", std::to_string(lab.number)},
                    {"title", lab.title(languageCode(language))},
                    {"handout", handout(tree, lab, language)},
                    {"folder", "labs/" + lab.id + "/"},
                    {"files", files}}) +
                "\n";
    }
    return text + "\n" + say("distribute.readme_build", {{"build", kStudentsBuildCommand}, {"tests", kStudentsTestCommand}}) +
           say("distribute.readme_use") + say("distribute.readme_windows") + tr(language, "distribute.readme_holds") + "\n";
}

} // namespace

void writeStudentsReadme(const fs::path& tree, const grader::LabCatalog& labs) {
    writeFileAtomically(tree / "README.md", readme(tree, labs, Language::En));
    writeFileAtomically(tree / "LISEZMOI.md", readme(tree, labs, Language::Fr));
}

} // namespace raylab::cli
