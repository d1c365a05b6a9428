#pragma once
// The labs, as their descriptions say: every labs/lab*/lab.toml (number, id, titles, the functions
// a student writes, the labs it uses, its figures and checks with their points). The grader, the
// report, `raylab distribute` and the docs test read them; nothing else names a lab or counts them.

#include "raylab/todo.h"
#include "src/scene_file.h"

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::grader {

struct LabFunction {
    std::string file; // in the lab's folder
    std::string name;
};

struct LabFigure {
    std::string id;              // the scene file's name without .toml
    std::filesystem::path scene; // labs/<lab>/scenes/<id>.toml (or the --scenes folder's)
    std::string handout;         // the handout's figure number, e.g. "3(a)"
    std::string captionEn, captionFr;
    double points = 0.;
    std::vector<int> uses; // the other labs whose code draws it (the lab's `uses` unless it says)

    const std::string& caption(const std::string& lang) const { return lang == "fr" ? captionFr : captionEn; }
};

struct LabCheck {
    std::string id; // short and stable: its results, mistakes.toml and checks.cpp name it; its title is
                    // [check_title] <id> of the lab's messages (titleInLanguage)
    double points = 0.;
    std::vector<int> uses; // the other labs whose code it calls (none unless it says)
    int line = 0;          // of its [[check]] in lab.toml
};

struct LabDescription {
    std::filesystem::path file; // its lab.toml
    int number = 0;
    std::string id; // its folder's name, lab<number>_<name>
    std::string titleEn, titleFr;
    std::vector<LabFunction> functions;
    std::vector<int> uses; // every lab a figure or a check of this one uses
    // The framework itself calls its functions (members of framework classes): a course that leaves it
    // out links its reference instead, "given" (lab.toml's framework_calls).
    bool frameworkCalls = false;
    std::vector<LabFigure> figures;
    std::vector<LabCheck> checks;

    const std::string& title(const std::string& lang) const { return lang == "fr" ? titleFr : titleEn; }
    const LabFigure* figure(const std::string& id) const;
    const LabCheck* check(const std::string& id) const;
    // The files a student writes (the functions' files, each once, in their order): what the grader
    // copies from a submission, each name unique in the course.
    std::vector<std::string> files() const;
};

struct LabCatalog {
    std::vector<LabDescription> labs; // by number
    // The labs the course leaves out whose functions the framework calls: every program links their
    // reference, and nothing grades, draws or reports them (by number). No lab's `uses` names them. In
    // a students' tree, only their number and id, from framework/given/<lab>/.
    std::vector<LabDescription> given;

    const LabDescription* lab(int number) const;
    const LabDescription* labOfId(const std::string& id) const; // by its folder's name
    const LabFigure* figure(const std::string& id) const;
    const LabDescription* labOfFigure(const std::string& id) const;
    // The number of the lab that lists the figure; 0 when none does.
    int labNumberOfFigure(const std::string& id) const;
    std::vector<int> numbers() const;
    // The points of a check; a check its lab's description does not name is a std::logic_error (the
    // grader's checks are those of lab.toml: functionChecks).
    double checkPoints(int lab, const std::string& name) const;
    // The points of a figure; `fallback` when no lab's description names it.
    double figurePoints(const std::string& id, double fallback) const;
};

// What a figure that reached a stub waits for: the stub's own message when it is the figure's lab,
// else the figure's lab's functions to write and, first, the earlier lab's stub it reached.
std::string waitingMessage(const LabCatalog& labs, const std::string& figureId, const NotDoneYet& todo);

// One lab.toml, checked on its own; throws std::runtime_error "FILE:LINE: key: problem".
// `scenes`: the folder its figures' scene files must be in; empty: the lab's own, <lab>/scenes/.
LabDescription loadLabDescription(const std::filesystem::path& file, const std::filesystem::path& scenes = {});

// The figures' scenes in the order of their lab, then of their id: the catalogue's (each lab's
// scenes/) when `folder` is empty, else the scene files of `folder` (loadSceneFolder; a scene no lab
// lists first).
std::vector<SceneDescription> loadFiguresInLabOrder(const std::filesystem::path& folder, const LabCatalog& labs);

// The folders the figures' scene files are in (an agent may read them), each once.
std::vector<std::filesystem::path> sceneFolders(const LabCatalog& labs);

// Every <labs>/lab*/lab.toml, checked together (numbers and figure ids unique, `uses` names labs
// that exist), those of the course's list (course.toml beside <labs>, course_list.h) kept, those it
// leaves out whose functions the framework calls given; throws std::runtime_error naming the file,
// line and key.
LabCatalog loadLabCatalog(const std::filesystem::path& labs, const std::filesystem::path& scenes = {});

} // namespace raylab::grader
