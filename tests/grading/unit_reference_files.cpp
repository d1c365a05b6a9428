// The grader's data files (each lab's framework/grader/labs/<lab>/references/): the mistakes' catalogue and each
// figure's reference description are read strictly, every problem naming the file, the line and the key.
#include "grader/judge/diagnosis.h"
#include "grader/judge/references.h"
#include "grader/judge/time_budget.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <random>
#include <tuple>

using namespace raylab;
using namespace raylab::grader;
namespace fs = std::filesystem;

namespace {

// A scratch reference folder, removed at the end.
struct Folder {
    fs::path root = fs::temp_directory_path() / ("raylab-reference-files-" + std::to_string(std::random_device{}()));
    Folder() { fs::create_directories(root); }
    ~Folder() { fs::remove_all(root); }
    Folder(const Folder&) = delete;
    Folder& operator=(const Folder&) = delete;

    fs::path write(const std::string& name, const std::string& text) const {
        std::ofstream(root / name) << text;
        return root / name;
    }
};

// What loading throws, with the folder's path taken off ("" when nothing is thrown).
template <class Load>
std::string errorOf(const Folder& folder, Load load) {
    try {
        load({folder.root});
    } catch (const std::runtime_error& e) {
        const std::string message = e.what(), prefix = (folder.root / "").string();
        return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
    }
    return "";
}

const std::string kMistake = R"toml([[mistake]]
id = "fovy_not_halved"
name = "fovy not halved"
name_fr = "fovy non divisé par deux"
lab = 2
function = "PerspectiveCamera::updateViewport (perspective_camera.cpp)"
hint = "use tan(fovy / 2)"
hint_fr = "utilisez tan(fovy / 2)"
check = "default_viewport"
)toml";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    return text.replace(text.find(from), from.size(), to);
}

const Image8 kImage{4, 2, std::vector<std::uint8_t>(4 * 2 * 3, 100)};

// A statistical reference of a 4 x 2 figure "fig", as `raylab references` writes it.
FigureReference statistical() {
    FigureReference f{"fig", 5, kImage, {{3, 1}}, StatisticalReference{}};
    f.stats->samples = 16;
    f.stats->mean.assign(kImage.rgb.size(), 100.f);
    f.stats->sampleSd.assign(kImage.rgb.size(), 16.f);
    f.stats->worstCorrectRmse = 4.;
    f.stats->rmseLimit = 5.;
    f.renderSeconds = 1.5; // written as 1500 ms
    return f;
}

} // namespace

TEST_SUITE("reference files") {

TEST_CASE("the mistakes' catalogue: a mistake is read whole") {
    const Folder folder;
    folder.write("mistakes.toml", kMistake + "label = \"2.1\"\n");
    const std::vector<Mistake> mistakes = loadMistakes({folder.root});
    REQUIRE(mistakes.size() == 1);
    CHECK(mistakes[0].id == "fovy_not_halved");
    CHECK(mistakes[0].nameFr == "fovy non divisé par deux");
    CHECK(mistakes[0].lab == 2);
    CHECK(mistakes[0].label == "2.1");
    CHECK(mistakes[0].check == "default_viewport");
    CHECK(loadMistakes({folder.root / "none"}).empty()); // no catalogue: no mistake to diagnose
}

TEST_CASE("the mistakes' catalogues of two labs: one id is one mistake, the second names the first's file") {
    const Folder first, second;
    first.write("mistakes.toml", kMistake);
    second.write("mistakes.toml", kMistake);
    CHECK(loadMistakes({first.root}).size() == 1);
    try {
        loadMistakes({first.root, second.root});
        FAIL("the same id in two catalogues was read");
    } catch (const std::runtime_error& e) {
        const std::string message = e.what();
        CHECK_MESSAGE(message.find((second.root / "mistakes.toml").string() + ":2: [[mistake]] #1 id: \"fovy_not_halved\" is also a mistake of " +
                                   (first.root / "mistakes.toml").string()) != std::string::npos, message);
    }
}

TEST_CASE("a mistake's signatures are kept with each figure's reference, in whichever lab's folder it is") {
    // The mistake is lab 2's (its catalogue in `catalogue`); "later" is a later lab whose figure it changes.
    const Folder catalogue, later;
    catalogue.write("mistakes.toml", kMistake);
    writeReference(later.root, statistical()); // figure "fig"
    const Image8 own{4, 2, std::vector<std::uint8_t>(4 * 2 * 3, 10)}, changed{4, 2, std::vector<std::uint8_t>(4 * 2 * 3, 20)};
    CHECK(signatureFolder({catalogue.root, later.root}, "fig", "fovy_not_halved") == later.root / "mistakes/fovy_not_halved");
    CHECK(signatureFolder({catalogue.root, later.root}, "own", "fovy_not_halved") == catalogue.root / "mistakes/fovy_not_halved");
    fs::create_directories(catalogue.root / "mistakes/fovy_not_halved");
    fs::create_directories(later.root / "mistakes/fovy_not_halved");
    fs::create_directories(later.root / "mistakes/a_left_out_labs_mistake");
    writePng(catalogue.root / "mistakes/fovy_not_halved/own.png", own);
    writePng(later.root / "mistakes/fovy_not_halved/fig.png", changed);
    writePng(later.root / "mistakes/a_left_out_labs_mistake/fig.png", own); // no catalogue lists it: not read
    const std::vector<Mistake> mistakes = loadMistakes({catalogue.root, later.root});
    REQUIRE(mistakes.size() == 1);
    REQUIRE(mistakes[0].signatures.size() == 2);
    CHECK(mistakes[0].signatures[0].first == "own");
    CHECK(mistakes[0].signatures[0].second.rgb == own.rgb);
    CHECK(mistakes[0].signatures[1].first == "fig");
    CHECK(mistakes[0].signatures[1].second.rgb == changed.rgb);
    CHECK(loadMistakes({later.root}).empty()); // signatures alone make no mistake
}

TEST_CASE("the mistakes' catalogue: an unknown key, a wrong type, a NaN or a missing value names the file, line and key") {
    const Folder folder;
    const auto error = [&](const std::string& text) {
        folder.write("mistakes.toml", text);
        return errorOf(folder, loadMistakes);
    };
    CHECK(error(kMistake + "hint_de = \"x\"\n") ==
          "mistakes.toml:10: [[mistake]] #1 hint_de: unknown key (known keys: id, name, name_fr, hint, hint_fr, label, "
          "lab, function, check, check_hint)");
    CHECK(error(replaced(kMistake, "lab = 2", "lab = \"2\"")) ==
          "mistakes.toml:5: [[mistake]] #1 lab: expected an integer, got a string");
    CHECK(error(replaced(kMistake, "lab = 2", "lab = nan")) ==
          "mistakes.toml:5: [[mistake]] #1 lab: expected an integer, got a number");
    CHECK(error(replaced(kMistake, "lab = 2", "lab = 0")) == "mistakes.toml:5: [[mistake]] #1 lab: 0 is out of range [1, 2147483647]");
    CHECK(error(kMistake + replaced(kMistake, "name = \"fovy not halved\"\n", "")) ==
          "mistakes.toml:10: [[mistake]] #2 name: missing");
    CHECK(error(replaced(kMistake, "hint = \"use tan(fovy / 2)\"", "hint = 2")) ==
          "mistakes.toml:7: [[mistake]] #1 hint: expected a string, got an integer");
    // Its signatures are read from mistakes/<id>/: an id that is a path is refused.
    CHECK(error(replaced(kMistake, "\"fovy_not_halved\"", "\"../fovy\"")) ==
          "mistakes.toml:2: [[mistake]] #1 id: \"../fovy\" is not a plain folder name (letters, digits, '_' and '-')");
    CHECK(error("mistakes = 1\n") == "mistakes.toml:1: mistakes: unknown key (known keys: mistake)");
    CHECK(error("[mistake]\nid = \"x\"\n") == "mistakes.toml:1: [[mistake]]: expected [[mistake]] tables");
    CHECK(error("[[mistake]\n").rfind("mistakes.toml:1:", 0) == 0);
}

TEST_CASE("a reference's description: what `raylab references` writes is read back") {
    const Folder folder;
    writeReference(folder.root, statistical());
    const ReferenceSet set = loadReferences({folder.root});
    REQUIRE(set.figures.size() == 1);
    const FigureReference& f = set.figures[0];
    CHECK(f.id == "fig");
    CHECK(f.lab == 5);
    CHECK(f.ambiguous == std::vector<std::pair<int, int>>{{3, 1}});
    REQUIRE(f.stats);
    CHECK(f.stats->samples == 16);
    CHECK(f.stats->rmseLimit == 5.);
    CHECK(f.stats->worstCorrectRmse == 4.);
    CHECK(f.renderSeconds == 1.5);
}

TEST_CASE("a lab's time budget: the factor times the reference's time on its figures, never under the floor") {
    ReferenceSet set;
    for (const auto& [id, lab, seconds] : {std::tuple{"a", 2, 0.5}, {"b", 2, 1.}, {"c", 3, 0.01}}) {
        FigureReference f{id, lab, kImage, {}, {}};
        f.renderSeconds = seconds;
        set.figures.push_back(f);
    }
    const TimeBudget budget{20., 5.};
    CHECK(labBudgetSeconds(set, 2, budget) == 30.); // 20 x (0.5 + 1)
    CHECK(labBudgetSeconds(set, 3, budget) == 5.);  // 20 x 0.01, below the floor
    CHECK(labBudgetSeconds(set, 4, budget) == 5.);  // no figure: checks only
}

TEST_CASE("a reference's description: an unknown key, a wrong type or a NaN names the file, line and key") {
    const Folder folder;
    writeReference(folder.root, statistical());
    std::string written;
    {
        std::ifstream in(folder.root / "fig.toml");
        written.assign(std::istreambuf_iterator<char>(in), {});
    }
    REQUIRE(written.find("\nlab = 5\n") != std::string::npos);
    const auto error = [&](const std::string& text) {
        folder.write("fig.toml", text);
        return errorOf(folder, loadReferences);
    };
    const auto lineOf = [&](const std::string& key) { // the line of `key = ` in `written`
        const std::size_t at = written.find("\n" + key + " = ");
        REQUIRE(at != std::string::npos);
        return std::to_string(std::count(written.begin(), written.begin() + std::ptrdiff_t(at) + 1, '\n') + 1);
    };
    CHECK(error(written + "colour = 1\n") ==
          "fig.toml:" + std::to_string(std::count(written.begin(), written.end(), '\n') + 1) +
              ": colour: unknown key (known keys: lab, kind, render_milliseconds, ambiguous, samples, rmse_limit, worst_correct_rmse, "
              "bias_lsb, outlier_z)");
    struct Case {
        std::string from, to, key, problem; // `from` replaced by `to`: the error at the line of `key`
    };
    const Case cases[] = {
        {"lab = 5", "lab = \"5\"", "lab", "expected an integer, got a string"},
        {"samples = 16", "samples = 16.0", "samples", "expected an integer, got a number"},
        {"rmse_limit = 5.0", "rmse_limit = nan", "rmse_limit", "must be finite, got nan"},
        {"outlier_z = 6.0", "outlier_z = inf", "outlier_z", "must be finite, got inf"},
        {"bias_lsb = ", "bias_lsb = 'x' #", "bias_lsb", "expected a number, got a string"},
        {"[ [ 3, 1 ] ]", "[ [ 4, 1 ] ]", "ambiguous", "4 is out of range [0, 3]"},
        {"[ [ 3, 1 ] ]", "[ 3, 1 ]", "ambiguous", "expected [i, j], a pixel's column and row"},
        // A deterministic reference has no statistical threshold.
        {"'statistical'", "'deterministic'", "samples", "only has a meaning with kind = \"statistical\""},
    };
    for (const Case& c : cases)
        CHECK(error(replaced(written, c.from, c.to)) == "fig.toml:" + lineOf(c.key) + ": " + c.key + ": " + c.problem);
}


TEST_CASE("a reference picture is written again only when its pixels change") {
    const Folder folder;
    const fs::path file = folder.root / "fig.png";
    Image8 image{2, 1, {10, 20, 30, 40, 50, 60}};
    CHECK(writePngIfChanged(file, image));
    // The same pixels in other bytes (as another encoder would write them): left as they are.
    { std::ofstream(file, std::ios::binary | std::ios::app) << "bytes after IEND"; }
    const std::string encoded = [&] {
        std::ifstream in(file, std::ios::binary);
        return std::string{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }();
    CHECK_FALSE(writePngIfChanged(file, image));
    std::ifstream in(file, std::ios::binary);
    CHECK(std::string{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()} == encoded);
    image.rgb[4] = 51;
    CHECK(writePngIfChanged(file, image));
    CHECK(readImage(file).rgb == image.rgb);
    // Another size is a change, and so is a file that is no picture.
    CHECK(writePngIfChanged(file, Image8{1, 1, {1, 2, 3}}));
    folder.write("broken.png", "not a png");
    CHECK(writePngIfChanged(folder.root / "broken.png", image));
    CHECK(readImage(folder.root / "broken.png").rgb == image.rgb);
}

} // TEST_SUITE
