#include "grader/course_list.h"

#include "src/messages.h"
#include "src/toml_reader.h"

#include <algorithm>
#include <limits>

namespace raylab::grader {

namespace fs = std::filesystem;

fs::path courseFile(const fs::path& labs) { return labs.parent_path() / "course.toml"; }

std::optional<std::vector<int>> loadCourseList(const fs::path& file, const std::vector<int>& found) {
    std::error_code error;
    if (!fs::is_regular_file(file, error)) return std::nullopt;
    const toml::table root = parseTomlFile(file);
    const TomlReader r(file);
    r.onlyKeys(root, "", {"labs"});
    const toml::array* list = r.array(root, "", "labs");
    if (list == nullptr || list->empty())
        r.fail(list != nullptr ? static_cast<const toml::node*>(list) : &root, "labs", tr("toml.course_labs"));
    std::vector<int> numbers;
    for (const toml::node& n : *list) {
        const int number = int(r.integerOf(n, "labs", 1, std::numeric_limits<int>::max()));
        if (std::find(numbers.begin(), numbers.end(), number) != numbers.end())
            r.fail(&n, "labs", tr("toml.course_twice", {{"number", std::to_string(number)}}));
        if (std::find(found.begin(), found.end(), number) == found.end())
            r.fail(&n, "labs", tr("toml.course_no_lab", {{"number", std::to_string(number)}}));
        numbers.push_back(number);
    }
    return numbers;
}

} // namespace raylab::grader
