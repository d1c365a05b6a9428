// raylab class-page OUT: the class page, the similar submissions and the gradebook files, remade from
// a grade-class run's results (grade-class makes them too, at its end); nothing is graded again.
#include "commands.h"

#include "grader/class_page/class_page.h"
#include "grader/class_page/gradebook.h"
#include "grader/class_page/similarity.h"
#include "grader/judge/diagnosis.h"
#include "src/messages.h"
#include "src/text.h"

#include <cstdio>
#include <memory>
#include <stdexcept>

namespace raylab::cli {

namespace fs = std::filesystem;
using namespace raylab::grader;

std::vector<RosterEntry> classRoster(const std::string& roster) {
    if (roster.empty()) return {};
    try {
        return readRoster(roster);
    } catch (const std::exception& e) {
        throw std::runtime_error(tr("class_page.roster_problem", {{"problem", e.what()}}));
    }
}

void remakeClassPage(const fs::path& out, const std::vector<RosterEntry>& roster) {
    const ClassResults results = loadClassResults(out);
    const LabCatalog labs = courseLabs();
    const std::vector<Mistake> mistakes = loadMistakes(referenceFolders(""));
    const GradebookFiles gradebook = writeGradebooks(results, roster, out);
    const SimilarityReport similarity = findSimilarSubmissions(results, labs, labsFolder(), out / "similarity" / "compared");
    writeClassPage({results, labs, mistakes, similarity, gradebook}, out);
    for (const std::string& p : results.problems) std::printf("%s\n", printableText(p).c_str());
    if (!similarity.note.empty()) std::printf("%s\n", similarity.note.c_str());
    for (const auto& [names, id] : {std::pair{&gradebook.unknown, "class_page.roster_unknown"},
                                    {&gradebook.missing, "class_page.roster_missing"},
                                    {&gradebook.unreadable, "class_page.gradebook_unreadable"}})
        if (!names->empty()) {
            std::string joined;
            for (const std::string& n : *names) joined += " " + n;
            std::printf("%s%s\n", tr(id, {{"count", std::to_string(names->size())}}).c_str(), joined.c_str());
        }
    std::printf("%s\n", tr("class_page.written", {{"page", printablePath(out / "index.html")}}).c_str());
}

void addClassPageCommand(CLI::App& app, Context&) {
    auto out = std::make_shared<std::string>("out/class");
    auto roster = std::make_shared<std::string>();
    CLI::App* command = app.add_subcommand("class-page", tr("cli.class_page"));
    command->add_option(tr("cli.type.DIR"), *out, tr("cli.class_page_out"))->check(CLI::ExistingDirectory);
    command->add_option("--roster", *roster, tr("cli.grade_class_roster"))->check(CLI::ExistingFile);
    command->callback([out, roster] { remakeClassPage(*out, classRoster(*roster)); });
}

} // namespace raylab::cli
