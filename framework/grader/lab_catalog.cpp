#include "grader/lab_catalog.h"

#include "grader/course_list.h"

#include "src/messages.h"
#include "src/text.h"
#include "src/toml_reader.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>

namespace raylab::grader {

namespace fs = std::filesystem;

namespace {

// A lab's `uses`, or an item's: lab numbers.
std::optional<std::vector<int>> labs(const TomlReader& r, const toml::table& t, const std::string& where) {
    const toml::array* list = r.array(t, where, "uses");
    if (list == nullptr) return std::nullopt;
    std::vector<int> numbers;
    for (const toml::node& n : *list) {
        const std::optional<int64_t> value = n.value_exact<int64_t>();
        if (!value || *value < 1) r.fail(&n, where + "uses", "expected a list of lab numbers, e.g. [2, 3]");
        numbers.push_back(int(*value));
    }
    return numbers;
}

double points(const TomlReader& r, const toml::table& t, const std::string& where) {
    const double value = r.requiredNumber(t, where, "points");
    if (value < 0.) r.fail(t.get("points"), where + "points", "points must be a number >= 0");
    return value;
}

// `{ en = "...", fr = "..." }`
std::pair<std::string, std::string> inTwoLanguages(const TomlReader& r, const toml::table& t, const std::string& where,
                                                   std::string_view key) {
    const toml::node* node = t.get(key);
    const toml::table* both = node != nullptr ? node->as_table() : nullptr;
    if (both == nullptr)
        r.fail(node != nullptr ? node : &t, where + std::string(key), "expected { en = \"...\", fr = \"...\" }");
    const std::string inner = where + std::string(key) + ".";
    r.onlyKeys(*both, inner, {"en", "fr"});
    return {r.text(*both, inner, "en"), r.text(*both, inner, "fr")};
}

// The [[key]] tables, each read by readOne(table, "[[key]] #n ").
template <class Item, class ReadOne>
std::vector<Item> list(const TomlReader& r, const toml::table& root, std::string_view key, ReadOne readOne) {
    std::vector<Item> items;
    const std::vector<const toml::table*> tables = r.tables(root, key);
    for (std::size_t k = 0; k < tables.size(); ++k)
        items.push_back(readOne(*tables[k], "[[" + std::string(key) + "]] #" + std::to_string(k + 1) + " "));
    return items;
}

bool contains(const std::vector<int>& list, int value) {
    return std::find(list.begin(), list.end(), value) != list.end();
}

// A lab file's name as a submission's copy and a CMake list can hold it: no folder, no quote, no `;`.
bool plainFileName(const std::string& name) {
    const bool plain = !name.empty() && name[0] != '.' && std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
    });
    return plain && name.size() > 4 && name.compare(name.size() - 4, 4, ".cpp") == 0;
}

// The N of a folder named lab<N>_<name> (N without a leading zero), as CMake reads it
// (cmake/RaylabLabs.cmake); nullopt for any other name.
std::optional<int> folderNumber(const std::string& folder) {
    const std::size_t underscore = folder.find('_');
    if (folder.rfind("lab", 0) != 0 || underscore == std::string::npos || underscore + 1 == folder.size() ||
        underscore == 3 || folder[3] == '0')
        return std::nullopt;
    const char* first = folder.data() + 3;
    const char* last = folder.data() + underscore;
    int number = 0;
    const auto [end, error] = std::from_chars(first, last, number);
    const bool digits = std::all_of(first, last, [](char c) { return c >= '0' && c <= '9'; });
    if (!digits || error != std::errc() || end != last) return std::nullopt;
    return number;
}

// The lab's number and id, which its folder's name lab<N>_<name> says too (CMake builds the labs
// from their folders' names without reading lab.toml), its titles and the labs it uses.
void readHeading(const TomlReader& r, const toml::table& root, const fs::path& file, LabDescription& lab) {
    lab.number = int(r.requiredInteger(root, "", "number", 1, std::numeric_limits<int>::max()));
    lab.id = r.text(root, "", "id");
    const std::string folder = file.parent_path().filename().string();
    if (lab.id != folder) r.fail(root.get("id"), "id", "\"" + lab.id + "\" is not the folder's name, " + folder);
    const std::optional<int> number = folderNumber(folder);
    if (!number) r.fail(root.get("id"), "id", tr("toml.lab_folder", {{"folder", folder}}));
    if (lab.number != *number)
        r.fail(root.get("number"), "number", tr("toml.lab_number", {{"number", std::to_string(lab.number)}, {"folder", folder}}));
    std::tie(lab.titleEn, lab.titleFr) = inTwoLanguages(r, root, "", "title");
    lab.uses = labs(r, root, "").value_or(std::vector<int>{});
    if (contains(lab.uses, lab.number)) r.fail(root.get("uses"), "uses", "a lab does not use itself");
    lab.frameworkCalls = r.boolean(root, "", "framework_calls").value_or(false);
    // The kinds of objects and of lights it brings: classes its folder's shapes.h and lights.h declare,
    // which CMake lists for Scene (raylab/scene.h) and its grading folder's shapes.cpp and lights.cpp register.
    for (const std::string role : {"shapes", "lights"}) {
        const toml::array* classes = r.array(root, "", role);
        if (classes == nullptr) continue;
        for (const toml::node& n : *classes) {
            const std::string name = r.stringOf(n, role);
            const bool identifier = !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0])) &&
                                    std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
            if (!identifier) r.fail(&n, role, "\"" + name + "\" is not the name of a C++ class");
        }
        std::error_code error;
        if (!classes->empty() && !fs::is_regular_file(file.parent_path() / (role + ".h"), error))
            r.fail(root.get(role), role, "no " + role + ".h beside " + file.filename().string() + " to declare them");
    }
}

std::vector<LabFunction> readFunctions(const TomlReader& r, const toml::table& root, const fs::path& file) {
    return list<LabFunction>(r, root, "function", [&](const toml::table& t, const std::string& where) {
        r.onlyKeys(t, where, {"file", "name"});
        LabFunction f{r.text(t, where, "file"), r.text(t, where, "name")};
        // The grader copies a submission's files under these names and CMake lists them: a plain name only.
        if (!plainFileName(f.file))
            r.fail(t.get("file"), where + "file",
                   "\"" + f.file + "\" is not a plain file name (letters, digits, '_', '-' and '.', ending in .cpp)");
        std::error_code error;
        if (!fs::is_regular_file(file.parent_path() / f.file, error))
            r.fail(t.get("file"), where + "file", "no file " + f.file + " beside " + file.filename().string());
        return f;
    });
}

// An item uses what it says, which must be among the lab's `uses`.
std::vector<int> itemUses(const TomlReader& r, const LabDescription& lab, const toml::table& t, const std::string& where,
                          const std::vector<int>& fallback) {
    const std::vector<int> uses = labs(r, t, where).value_or(fallback);
    for (int other : uses)
        if (!contains(lab.uses, other))
            r.fail(t.get("uses"), where + "uses", "lab " + std::to_string(other) + " is not in the lab's uses");
    return uses;
}

std::vector<LabFigure> readFigures(const TomlReader& r, const toml::table& root, const LabDescription& lab,
                                   const fs::path& scenes) {
    return list<LabFigure>(r, root, "figure", [&](const toml::table& t, const std::string& where) {
        r.onlyKeys(t, where, {"id", "scene", "handout", "caption", "points", "uses"});
        LabFigure f;
        f.id = r.text(t, where, "id");
        f.scene = scenes / r.text(t, where, "scene");
        if (f.scene.stem().string() != f.id || f.scene.extension() != ".toml")
            r.fail(t.get("scene"), where + "scene",
                   "expected " + f.id + ".toml (a figure's id is its scene file's name)");
        std::error_code error;
        if (!fs::is_regular_file(f.scene, error))
            r.fail(t.get("scene"), where + "scene", "no scene file " + f.scene.string());
        f.handout = r.text(t, where, "handout");
        std::tie(f.captionEn, f.captionFr) = inTwoLanguages(r, t, where, "caption");
        f.points = points(r, t, where);
        f.uses = itemUses(r, lab, t, where, lab.uses);
        return f;
    });
}

std::vector<LabCheck> readChecks(const TomlReader& r, const toml::table& root, const LabDescription& lab) {
    return list<LabCheck>(r, root, "check", [&](const toml::table& t, const std::string& where) {
        r.onlyKeys(t, where, {"id", "points", "uses"});
        LabCheck c{r.text(t, where, "id"), points(r, t, where), itemUses(r, lab, t, where, {}), int(t.source().begin.line)};
        // It keys a message ([check_title] <id>), a command's argument (raylab grade --item) and a
        // workflow step's id: short, and the same in every language.
        const auto lower = [](char k) { return k >= 'a' && k <= 'z'; };
        const bool word = !c.id.empty() && c.id.size() <= 40 && lower(c.id.front()) &&
                          std::all_of(c.id.begin(), c.id.end(), [&](char k) { return lower(k) || (k >= '0' && k <= '9') || k == '_'; });
        if (!word)
            r.fail(t.get("id"), where + "id",
                   "\"" + printableText(c.id) + "\": a check's id is 1 to 40 lower-case letters, digits and _, from a letter "
                   "(its sentence is its title, [check_title] in the grading folder's messages)");
        return c;
    });
}

// Figure ids and check ids share one namespace within a lab.
void rejectDuplicateNames(const TomlReader& r, const toml::table& root, const LabDescription& lab) {
    std::map<std::string, int> seen;
    for (const LabFigure& f : lab.figures)
        if (seen[f.id]++) r.fail(root.get("figure"), "figure", "the id " + f.id + " is there twice");
    for (const LabCheck& c : lab.checks)
        if (seen[c.id]++) r.fail(root.get("check"), "check", "the id \"" + c.id + "\" is there twice");
}

// A given lab is the framework's: what uses it uses the framework, not a lab graded on its own.
void forgetGivenLabs(std::vector<int>& uses, const std::vector<LabDescription>& given) {
    std::erase_if(uses, [&](int n) {
        return std::any_of(given.begin(), given.end(), [&](const LabDescription& g) { return g.number == n; });
    });
}

// Keeps the labs of the course's list; of the others, those whose functions the framework calls are given.
void leaveOut(LabCatalog& catalog, const std::vector<int>& course) {
    std::vector<LabDescription> kept;
    for (LabDescription& lab : catalog.labs) {
        if (contains(course, lab.number)) kept.push_back(std::move(lab));
        else if (lab.frameworkCalls) catalog.given.push_back(std::move(lab));
    }
    catalog.labs = std::move(kept);
}

// A students' tree has no lab.toml of a given lab, only its reference, framework/given/<lab>/ (`raylab
// distribute`), whose folder's name says its number and id. Then no lab's `uses` names a given lab.
void addGivenReferences(LabCatalog& catalog, const fs::path& labs) {
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(labs.parent_path() / "framework" / "given", error)) {
        const std::string id = entry.path().filename().string();
        const std::optional<int> number = folderNumber(id);
        const auto known = [&](const LabDescription& l) { return number && l.number == *number; };
        if (!entry.is_directory() || !number || std::any_of(catalog.labs.begin(), catalog.labs.end(), known) ||
            std::any_of(catalog.given.begin(), catalog.given.end(), known))
            continue;
        LabDescription lab;
        lab.file = entry.path();
        lab.number = *number;
        lab.id = id;
        lab.frameworkCalls = true;
        catalog.given.push_back(std::move(lab));
    }
    std::sort(catalog.given.begin(), catalog.given.end(), [](const auto& a, const auto& b) { return a.number < b.number; });
    for (LabDescription& lab : catalog.labs) {
        forgetGivenLabs(lab.uses, catalog.given);
        for (LabFigure& f : lab.figures) forgetGivenLabs(f.uses, catalog.given);
        for (LabCheck& c : lab.checks) forgetGivenLabs(c.uses, catalog.given);
    }
}

} // namespace

const LabFigure* LabDescription::figure(const std::string& wanted) const {
    for (const LabFigure& f : figures)
        if (f.id == wanted) return &f;
    return nullptr;
}

const LabCheck* LabDescription::check(const std::string& wanted) const {
    for (const LabCheck& c : checks)
        if (c.id == wanted) return &c;
    return nullptr;
}

std::vector<std::string> LabDescription::files() const {
    std::vector<std::string> names;
    for (const LabFunction& f : functions)
        if (std::find(names.begin(), names.end(), f.file) == names.end()) names.push_back(f.file);
    return names;
}

const LabDescription* LabCatalog::lab(int number) const {
    for (const LabDescription& l : labs)
        if (l.number == number) return &l;
    return nullptr;
}

const LabDescription* LabCatalog::labOfId(const std::string& id) const {
    for (const LabDescription& l : labs)
        if (l.id == id) return &l;
    return nullptr;
}

const LabFigure* LabCatalog::figure(const std::string& id) const {
    const LabDescription* l = labOfFigure(id);
    return l != nullptr ? l->figure(id) : nullptr;
}

const LabDescription* LabCatalog::labOfFigure(const std::string& id) const {
    for (const LabDescription& l : labs)
        if (l.figure(id) != nullptr) return &l;
    return nullptr;
}

int LabCatalog::labNumberOfFigure(const std::string& id) const {
    const LabDescription* l = labOfFigure(id);
    return l != nullptr ? l->number : 0;
}

std::vector<int> LabCatalog::numbers() const {
    std::vector<int> n;
    for (const LabDescription& l : labs)
        n.push_back(l.number);
    return n;
}

double LabCatalog::checkPoints(int number, const std::string& name) const {
    const LabDescription* l = lab(number);
    const LabCheck* c = l != nullptr ? l->check(name) : nullptr;
    if (c == nullptr) throw std::logic_error("lab " + std::to_string(number) + " has no check \"" + name + "\"");
    return c->points;
}

double LabCatalog::figurePoints(const std::string& id, double fallback) const {
    const LabFigure* f = figure(id);
    return f != nullptr ? f->points : fallback;
}

LabDescription loadLabDescription(const fs::path& file, const fs::path& scenes) {
    const toml::table root = parseTomlFile(file);
    const TomlReader r(file);
    r.onlyKeys(root, "", {"number", "id", "title", "uses", "framework_calls", "shapes", "lights", "function", "figure", "check"});
    LabDescription lab;
    lab.file = file;
    readHeading(r, root, file, lab);
    lab.functions = readFunctions(r, root, file);
    lab.figures = readFigures(r, root, lab, scenes.empty() ? file.parent_path() / "scenes" : scenes);
    lab.checks = readChecks(r, root, lab);
    rejectDuplicateNames(r, root, lab);
    return lab;
}

std::vector<SceneDescription> loadFiguresInLabOrder(const fs::path& folder, const LabCatalog& labs) {
    if (folder.empty()) {
        std::vector<SceneDescription> scenes; // each lab's figures, by id
        for (const LabDescription& lab : labs.labs) {
            std::vector<SceneDescription> own;
            for (const LabFigure& f : lab.figures) own.push_back(loadSceneFile(f.scene));
            std::sort(own.begin(), own.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
            scenes.insert(scenes.end(), own.begin(), own.end());
        }
        return scenes;
    }
    std::vector<SceneDescription> scenes = loadSceneFolder(folder); // by id
    std::stable_sort(scenes.begin(), scenes.end(), [&](const auto& a, const auto& b) {
        return labs.labNumberOfFigure(a.id) < labs.labNumberOfFigure(b.id);
    });
    return scenes;
}

std::vector<fs::path> sceneFolders(const LabCatalog& labs) {
    std::vector<fs::path> folders;
    for (const LabDescription& lab : labs.labs)
        for (const LabFigure& f : lab.figures)
            if (std::find(folders.begin(), folders.end(), f.scene.parent_path()) == folders.end())
                folders.push_back(f.scene.parent_path());
    return folders;
}

LabCatalog loadLabCatalog(const fs::path& labs, const fs::path& scenes) {
    std::error_code error;
    if (!fs::is_directory(labs, error)) throw std::runtime_error("no labs folder " + labs.string());
    LabCatalog catalog;
    for (const auto& entry : fs::directory_iterator(labs)) {
        const fs::path file = entry.path() / "lab.toml";
        if (entry.is_directory() && entry.path().filename().string().rfind("lab", 0) == 0 &&
            fs::is_regular_file(file, error))
            catalog.labs.push_back(loadLabDescription(file, scenes));
    }
    if (catalog.labs.empty()) throw std::runtime_error("no lab description (lab*/lab.toml) in " + labs.string());
    std::sort(catalog.labs.begin(), catalog.labs.end(),
              [](const auto& a, const auto& b) { return a.number < b.number; });
    if (const std::optional<std::vector<int>> course = loadCourseList(courseFile(labs), catalog.numbers()))
        leaveOut(catalog, *course);
    addGivenReferences(catalog, labs);
    std::map<std::string, const LabDescription*> itemOwner, fileOwner; // the figures' and checks' ids, the files
    for (std::size_t k = 0; k < catalog.labs.size(); ++k) {
        const LabDescription& lab = catalog.labs[k];
        if (k > 0 && catalog.labs[k - 1].number == lab.number)
            throw std::runtime_error(lab.file.string() + ": number: " + std::to_string(lab.number) +
                                     " is also the number of " + catalog.labs[k - 1].file.string());
        for (int other : lab.uses)
            if (std::none_of(catalog.labs.begin(), catalog.labs.end(),
                             [&](const auto& l) { return l.number == other; }))
                throw std::runtime_error(lab.file.string() + ": uses: there is no lab " + std::to_string(other) +
                                         " in " + labs.string());
        // A file uploaded without its folder is put in its lab by its name alone.
        for (const std::string& name : lab.files())
            if (const auto [it, added] = fileOwner.emplace(name, &lab); !added)
                throw std::runtime_error(lab.file.string() + ": function: file " + name + " is also a file of " +
                                         it->second->file.string() + " (a lab file's name is unique in the course)");
        for (const LabFigure& f : lab.figures)
            if (const auto [it, added] = itemOwner.emplace(f.id, &lab); !added)
                throw std::runtime_error(lab.file.string() + ": figure: " + f.id + " is also a figure of " +
                                         it->second->file.string());
    }
    // A check's id keys its title in the merged messages and `raylab grade --item`: unique in the course.
    for (const LabDescription& lab : catalog.labs)
        for (const LabCheck& c : lab.checks)
            if (const auto [it, added] = itemOwner.emplace(c.id, &lab); !added && it->second != &lab)
                throw std::runtime_error(lab.file.string() + ":" + std::to_string(c.line) + ": check: " + c.id +
                                         " is also a check or a figure of " + it->second->file.string() +
                                         " (a check's id is unique in the course)");
    return catalog;
}

std::string waitingMessage(const LabCatalog& labs, const std::string& figureId, const NotDoneYet& todo) {
    const LabDescription* own = labs.labOfFigure(figureId);
    const std::string stubLab = todo.lab().substr(todo.lab().find_last_of(' ') + 1); // "lab 2" -> "2"
    if (own == nullptr || std::to_string(own->number) == stubLab || own->functions.empty()) return todo.what();
    std::string functions;
    for (const LabFunction& f : own->functions) functions += (functions.empty() ? "" : ", ") + titleInLanguage(f.name);
    return tr("todo.waits", {{"lab", std::to_string(own->number)},
                             {"functions", functions},
                             {"folder", "labs/" + own->id + "/"},
                             {"first", stubLab},
                             {"function", titleInLanguage(todo.function())},
                             {"where", todo.file() + ":" + std::to_string(todo.line())}});
}

} // namespace raylab::grader
