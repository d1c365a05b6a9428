#include "grader/lab_catalog.h"

#include "src/messages.h"

#include <toml++/toml.h>

#include <algorithm>
#include <initializer_list>
#include <map>
#include <optional>
#include <stdexcept>

namespace raylab::grader {

namespace fs = std::filesystem;

namespace {

// Reads one lab.toml strictly: every problem names the file, the line and the key.
class Reader {
public:
    explicit Reader(fs::path file) : m_file(std::move(file)) {}

    [[noreturn]] void fail(const toml::node* node, const std::string& key, const std::string& problem) const {
        const int line = node != nullptr ? int(node->source().begin.line) : 0;
        throw std::runtime_error(m_file.string() + ":" + (line > 0 ? std::to_string(line) + ":" : std::string()) + " " +
                                 key + ": " + problem);
    }

    void onlyKeys(const toml::table& t, const std::string& where, std::initializer_list<std::string_view> keys) const {
        for (const auto& [key, node] : t)
            if (std::find(keys.begin(), keys.end(), key.str()) == keys.end()) {
                std::string known;
                for (std::string_view k : keys)
                    known += (known.empty() ? "" : ", ") + std::string(k);
                fail(&node, where + std::string(key.str()), "unknown key (expected " + known + ")");
            }
    }

    std::string text(const toml::table& t, const std::string& where, std::string_view key) const {
        const toml::node* node = t.get(key);
        if (node == nullptr) fail(&t, where + std::string(key), "missing");
        const std::optional<std::string> value = node->value_exact<std::string>();
        if (!value || value->empty()) fail(node, where + std::string(key), "expected a non-empty string");
        return *value;
    }

    double points(const toml::table& t, const std::string& where) const {
        const toml::node* node = t.get("points");
        if (node == nullptr) fail(&t, where + "points", "missing");
        const std::optional<double> value = node->value<double>();
        if (!value || *value < 0.) fail(node, where + "points", "points must be a number >= 0");
        return *value;
    }

    std::optional<std::vector<int>> labs(const toml::table& t, const std::string& where) const {
        const toml::node* node = t.get("uses");
        if (node == nullptr) return std::nullopt;
        const toml::array* list = node->as_array();
        if (list == nullptr) fail(node, where + "uses", "expected a list of lab numbers, e.g. [2, 3]");
        std::vector<int> numbers;
        for (const toml::node& n : *list) {
            const std::optional<int64_t> value = n.value_exact<int64_t>();
            if (!value || *value < 1) fail(&n, where + "uses", "expected a list of lab numbers, e.g. [2, 3]");
            numbers.push_back(int(*value));
        }
        return numbers;
    }

    // `{ en = "...", fr = "..." }`
    std::pair<std::string, std::string> inTwoLanguages(const toml::table& t, const std::string& where,
                                                       std::string_view key) const {
        const toml::node* node = t.get(key);
        const toml::table* both = node != nullptr ? node->as_table() : nullptr;
        if (both == nullptr)
            fail(node != nullptr ? node : &t, where + std::string(key), "expected { en = \"...\", fr = \"...\" }");
        const std::string inner = where + std::string(key) + ".";
        onlyKeys(*both, inner, {"en", "fr"});
        return {text(*both, inner, "en"), text(*both, inner, "fr")};
    }

    template <class Item, class ReadOne>
    std::vector<Item> list(const toml::table& root, std::string_view key, ReadOne readOne) const {
        std::vector<Item> items;
        const toml::node* node = root.get(key);
        if (node == nullptr) return items;
        const toml::array* array = node->as_array();
        if (array == nullptr || !array->is_array_of_tables())
            fail(node, std::string(key), "expected [[" + std::string(key) + "]] tables");
        for (std::size_t k = 0; k < array->size(); ++k)
            items.push_back(
                readOne(*(*array)[k].as_table(), "[[" + std::string(key) + "]] #" + std::to_string(k + 1) + " "));
        return items;
    }

    const fs::path& file() const { return m_file; }

private:
    fs::path m_file;
};

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

toml::table parseToml(const fs::path& file) {
    try {
        return toml::parse_file(file.string());
    } catch (const toml::parse_error& e) {
        throw std::runtime_error(file.string() + ":" + std::to_string(e.source().begin.line) +
                                 ": not valid TOML: " + std::string(e.description()));
    }
}

// The lab's number, id (its folder's name, "labN_..."), titles and the labs it uses.
void readHeading(const Reader& r, const toml::table& root, const fs::path& file, LabDescription& lab) {
    const toml::node* number = root.get("number");
    if (number == nullptr || !number->is_integer() || number->value_or(int64_t(0)) < 1)
        r.fail(number != nullptr ? number : &root, "number", "expected the lab's number, an integer >= 1");
    lab.number = int(number->value_or(int64_t(0)));
    lab.id = r.text(root, "", "id");
    const std::string folder = file.parent_path().filename().string();
    if (lab.id != folder) r.fail(root.get("id"), "id", "\"" + lab.id + "\" is not the folder's name, " + folder);
    const std::string prefix = "lab" + std::to_string(lab.number) + "_";
    if (lab.id.rfind(prefix, 0) != 0)
        r.fail(root.get("id"), "id",
               "\"" + lab.id + "\" must begin with " + prefix + " (number = " + std::to_string(lab.number) + ")");
    std::tie(lab.titleEn, lab.titleFr) = r.inTwoLanguages(root, "", "title");
    lab.uses = r.labs(root, "").value_or(std::vector<int>{});
    if (contains(lab.uses, lab.number)) r.fail(root.get("uses"), "uses", "a lab does not use itself");
}

std::vector<LabFunction> readFunctions(const Reader& r, const toml::table& root, const fs::path& file) {
    return r.list<LabFunction>(root, "function", [&](const toml::table& t, const std::string& where) {
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
std::vector<int> itemUses(const Reader& r, const LabDescription& lab, const toml::table& t, const std::string& where,
                          const std::vector<int>& fallback) {
    const std::vector<int> uses = r.labs(t, where).value_or(fallback);
    for (int other : uses)
        if (!contains(lab.uses, other))
            r.fail(t.get("uses"), where + "uses", "lab " + std::to_string(other) + " is not in the lab's uses");
    return uses;
}

std::vector<LabFigure> readFigures(const Reader& r, const toml::table& root, const LabDescription& lab,
                                   const fs::path& scenes) {
    return r.list<LabFigure>(root, "figure", [&](const toml::table& t, const std::string& where) {
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
        std::tie(f.captionEn, f.captionFr) = r.inTwoLanguages(t, where, "caption");
        f.points = r.points(t, where);
        f.uses = itemUses(r, lab, t, where, lab.uses);
        return f;
    });
}

std::vector<LabCheck> readChecks(const Reader& r, const toml::table& root, const LabDescription& lab) {
    return r.list<LabCheck>(root, "check", [&](const toml::table& t, const std::string& where) {
        r.onlyKeys(t, where, {"name", "points", "uses"});
        LabCheck c{r.text(t, where, "name"), r.points(t, where), itemUses(r, lab, t, where, {}), int(t.source().begin.line)};
        if (c.name.find_first_of(",*?") != std::string::npos)
            r.fail(t.get("name"), where + "name", "\"" + c.name + "\": doctest's filters split names on , * ?");
        return c;
    });
}

// Figure ids and check names share one namespace within a lab.
void rejectDuplicateNames(const Reader& r, const toml::table& root, const LabDescription& lab) {
    std::map<std::string, int> seen;
    for (const LabFigure& f : lab.figures)
        if (seen[f.id]++) r.fail(root.get("figure"), "figure", "the id " + f.id + " is there twice");
    for (const LabCheck& c : lab.checks)
        if (seen[c.name]++) r.fail(root.get("check"), "check", "the name \"" + c.name + "\" is there twice");
}

} // namespace

const LabFigure* LabDescription::figure(const std::string& wanted) const {
    for (const LabFigure& f : figures)
        if (f.id == wanted) return &f;
    return nullptr;
}

const LabCheck* LabDescription::check(const std::string& wanted) const {
    for (const LabCheck& c : checks)
        if (c.name == wanted) return &c;
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
    const toml::table root = parseToml(file);
    const Reader r(file);
    r.onlyKeys(root, "", {"number", "id", "title", "uses", "function", "figure", "check"});
    LabDescription lab;
    lab.file = file;
    readHeading(r, root, file, lab);
    lab.functions = readFunctions(r, root, file);
    lab.figures = readFigures(r, root, lab, scenes);
    lab.checks = readChecks(r, root, lab);
    rejectDuplicateNames(r, root, lab);
    return lab;
}

std::vector<SceneDescription> loadFiguresInLabOrder(const fs::path& folder, const LabCatalog& labs) {
    std::vector<SceneDescription> scenes = loadSceneFolder(folder); // by id
    std::stable_sort(scenes.begin(), scenes.end(), [&](const auto& a, const auto& b) {
        return labs.labNumberOfFigure(a.id) < labs.labNumberOfFigure(b.id);
    });
    return scenes;
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
    std::map<std::string, const LabDescription*> figureOwner, fileOwner;
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
            if (const auto [it, added] = figureOwner.emplace(f.id, &lab); !added)
                throw std::runtime_error(lab.file.string() + ": figure: " + f.id + " is also a figure of " +
                                         it->second->file.string());
    }
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
