// The grader's copy of a submission (course/submission_copy.h): the lab files found wherever students
// put them, by the names lab.toml declares, regular files only; everything else listed, never copied.
#include "grader/course/submission_copy.h"
#include "support/files.h"

#include "src/messages.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <fstream>
#include <random>

#ifndef _WIN32
#include <sys/stat.h>
#include <unistd.h>
#endif

namespace fs = std::filesystem;
using namespace raylab::grader;
using raylab::test::readFile;

namespace {

const fs::path kSource = RAYLAB_SOURCE_DIR;

struct Upload {
    fs::path root = fs::temp_directory_path() / ("raylab-copy-test-" + std::to_string(std::random_device{}()));
    fs::path submission = root / "submission", copy = root / "copy";
    LabCatalog catalog = loadLabCatalog(kSource / "labs");

    Upload() {
        raylab::setLanguage(raylab::Language::En);
        fs::create_directories(submission);
    }
    ~Upload() {
        std::error_code ignored;
        fs::remove_all(root, ignored);
    }
    Upload(const Upload&) = delete;
    Upload& operator=(const Upload&) = delete;

    void write(const fs::path& relative, const std::string& text) const {
        fs::create_directories((submission / relative).parent_path());
        std::ofstream(submission / relative, std::ios::binary) << text;
    }
    SubmissionCopy make() const { return copySubmission(submission, catalog, copy); }
    // Every file of the copy, as "<lab id>/<file>".
    std::vector<std::string> copied() const {
        std::vector<std::string> files;
        for (const auto& entry : fs::recursive_directory_iterator(copy))
            if (entry.is_regular_file()) files.push_back(entry.path().lexically_relative(copy).generic_string());
        std::sort(files.begin(), files.end());
        return files;
    }
};

bool listed(const SubmissionCopy& copy, const std::string& start) {
    return std::any_of(copy.ignored.begin(), copy.ignored.end(), [&](const std::string& line) { return line.rfind(start, 0) == 0; });
}

// The course's lab files, "a.cpp, b.cpp", and lab folders, "lab1_x/, lab2_y/", as the messages list them.
std::string courseFiles(const LabCatalog& catalog) {
    std::string files;
    for (const LabDescription& lab : catalog.labs)
        for (const std::string& file : lab.files()) files += (files.empty() ? "" : ", ") + file;
    return files;
}

std::string courseFolders(const LabCatalog& catalog) {
    std::string folders;
    for (const LabDescription& lab : catalog.labs) folders += (folders.empty() ? "" : ", ") + lab.id + "/";
    return folders;
}

} // namespace

TEST_SUITE("submission copy") {

TEST_CASE("lab folders: the declared files are copied under their lab's id; odd names are listed, never copied") {
    const Upload u;
    u.write("lab3_sphere/sphere_geometry.cpp", "// sphere\n");
    u.write("lab3_sphere/x;y.cpp", "not C++\n");
    u.write("lab3_sphere/${HOME}x.cpp", "not C++\n");
    u.write("lab3_sphere/it's a \"file\".cpp", "not C++\n");
    u.write("lab3_sphere/README.md", "notes\n");
    const SubmissionCopy copy = u.make();
    CHECK(u.copied() == std::vector<std::string>{"lab3_sphere/sphere_geometry.cpp"});
    CHECK(readFile(u.copy / "lab3_sphere/sphere_geometry.cpp") == "// sphere\n");
    CHECK(copy.labs == std::vector<int>{3});
    REQUIRE(copy.ignored.size() == 3); // the sources; README.md is not worth a line
    CHECK(listed(copy, "lab3_sphere/x;y.cpp: not a lab file"));
    CHECK(listed(copy, "lab3_sphere/${HOME}x.cpp: not a lab file"));
    CHECK(listed(copy, "lab3_sphere/it's a \"file\".cpp: not a lab file"));
    const std::string note = ignoredFilesNote(copy, u.catalog);
    CHECK(courseFiles(u.catalog).rfind("gradient.cpp, perspective_camera.cpp, sphere_geometry.cpp, ", 0) == 0);
    CHECK(note.rfind("left out of the grade (3; the lab files are " + courseFiles(u.catalog) + "):\n  lab3_sphere/", 0) == 0);
}

TEST_CASE("uploads as students make them: the files flat, folders named otherwise, labs/, a wrapping folder; "
          "__MACOSX and hidden files ignored") {
    // The course's lab files, <lab>/<file>, in its order, and their labs' numbers.
    std::vector<std::string> all;
    std::vector<int> numbers;
    for (const LabDescription& lab : loadLabCatalog(kSource / "labs").labs) {
        numbers.push_back(lab.number);
        for (const std::string& file : lab.files()) all.push_back(lab.id + "/" + file);
    }
    std::sort(all.begin(), all.end()); // as copied() lists them
    SUBCASE("flat") {
        const Upload u;
        for (const std::string& file : all) u.write(fs::path(file).filename(), file);
        u.write("__MACOSX/._look_at.cpp", "resource fork");
        u.write("__MACOSX/sphere_geometry.cpp", "resource fork"); // else listed as another copy
        u.write(".look_at.cpp.swp", "editor");
        u.write("look_at.cpp.orig", "backup");
        const SubmissionCopy copy = u.make();
        CHECK(u.copied() == all);
        for (const std::string& file : all) CHECK(readFile(u.copy / file) == file);
        CHECK(copy.labs == numbers);
        CHECK(copy.ignored.empty());
    }
    SUBCASE("folders named otherwise, inside a wrapping folder") {
        const Upload u;
        // Lab N's files in tp1/, "TP 2/", "Lab 3/", lab4-final/, tp_5/... by its number.
        const std::vector<std::string> forms{"tp_#", "tp#", "TP #", "Lab #", "lab#-final"};
        for (std::size_t k = 0; k < all.size(); ++k) {
            const int lab = std::stoi(all[k].substr(3)); // lab<N>_<name>/<file>
            std::string folder = forms[std::size_t(lab) % forms.size()];
            folder.replace(folder.find('#'), 1, std::to_string(lab));
            u.write(fs::path("my work") / folder / fs::path(all[k]).filename(), all[k]);
        }
        u.write("__MACOSX/my work/Lab 3/._sphere_geometry.cpp", "resource fork");
        CHECK(u.make().labs == numbers);
        CHECK(u.copied() == all);
        CHECK(readFile(u.copy / "lab3_sphere/sphere_geometry.cpp") == "lab3_sphere/sphere_geometry.cpp");
    }
    SUBCASE("the whole repository: labs/ wins over a stale copy deeper and a loose file") {
        const Upload u;
        for (const std::string& file : all) u.write(fs::path("raylab-main/labs") / file, file);
        u.write("raylab-main/out/grade-build/submission/lab3_sphere/sphere_geometry.cpp", "stale");
        u.write("raylab-main/sphere_geometry.cpp", "loose");
        u.write("raylab-main/tp3/sphere_geometry.cpp", "lab3_sphere/sphere_geometry.cpp"); // the same: not listed
        const SubmissionCopy copy = u.make();
        CHECK(u.copied() == all);
        CHECK(readFile(u.copy / "lab3_sphere/sphere_geometry.cpp") == "lab3_sphere/sphere_geometry.cpp");
        REQUIRE(copy.ignored.size() == 2);
        CHECK(listed(copy, "raylab-main/out/grade-build/submission/lab3_sphere/sphere_geometry.cpp: another copy, unlike "
                           "raylab-main/labs/lab3_sphere/sphere_geometry.cpp"));
        CHECK(listed(copy, "raylab-main/sphere_geometry.cpp: another copy"));
    }
}

TEST_CASE("no lab file: nothing copied, and the message says what to upload, in English and French") {
    const Upload u;
    u.write("notes.txt", "hello");
    const SubmissionCopy copy = u.make();
    CHECK(copy.labs.empty());
    CHECK(u.copied().empty());
    CHECK(courseFolders(u.catalog).rfind("lab1_first_image/, lab2_primary_rays/, ", 0) == 0);
    CHECK(noLabFileMessage(u.catalog) == "no lab file found: upload the lab files (" + courseFiles(u.catalog) +
                                             "), in their lab folders (" + courseFolders(u.catalog) +
                                             "), in a labs/ folder or on their own");
    raylab::setLanguage(raylab::Language::Fr);
    CHECK(noLabFileMessage(u.catalog).rfind("aucun fichier de TP trouvé\u00A0: déposez les fichiers des TP (gradient.cpp, ", 0) == 0);
    raylab::setLanguage(raylab::Language::En);
}

#ifndef _WIN32
TEST_CASE("nothing is followed: a labs/ link, a linked submission, a linked file, a pipe, a hard link, a huge file") {
    const fs::path solution = kSource / "solutions/lab3_sphere/sphere_geometry.cpp";
    SUBCASE("labs/ a link to the solutions") {
        const Upload u;
        fs::create_directory_symlink(kSource / "solutions", u.submission / "labs");
        const SubmissionCopy copy = u.make();
        CHECK(copy.labs.empty());
        CHECK(copy.ignored == std::vector<std::string>{"labs: a symbolic link, not followed"});
    }
    SUBCASE("the submission itself a link, named with a final slash") {
        const Upload u;
        fs::create_directory_symlink(kSource / "solutions", u.root / "alice");
        const SubmissionCopy copy = copySubmission(u.root.string() + "/alice/", u.catalog, u.copy);
        CHECK(copy.labs.empty());
        CHECK(copy.ignored == std::vector<std::string>{"alice: a symbolic link, not followed"});
    }
    SUBCASE("files that are not regular files of their own") {
        const Upload u;
        u.write("lab1_first_image/gradient.cpp", "// mine\n");
        fs::create_directories(u.submission / "lab3_sphere");
        fs::create_symlink(solution, u.submission / "lab3_sphere/sphere_geometry.cpp");
        REQUIRE(::mkfifo((u.submission / "lab3_sphere/ray_cast_integrator.cpp").c_str(), 0600) == 0); // would block a read
        fs::create_directories(u.root / "elsewhere");
        std::ofstream(u.root / "elsewhere/perspective_camera.cpp") << "// a classmate's\n";
        fs::create_hard_link(u.root / "elsewhere/perspective_camera.cpp", u.submission / "perspective_camera.cpp");
        const SubmissionCopy copy = u.make();
        CHECK(u.copied() == std::vector<std::string>{"lab1_first_image/gradient.cpp"});
        CHECK(copy.labs == std::vector<int>{1});
        CHECK(listed(copy, "lab3_sphere/sphere_geometry.cpp: a symbolic link, not followed"));
        CHECK(listed(copy, "lab3_sphere/ray_cast_integrator.cpp: not a regular file"));
        CHECK(listed(copy, "perspective_camera.cpp: a file with other names (a hard link), not read"));
        CHECK(copy.ignored.size() == 3);
    }
    SUBCASE("a file over the size limit") {
        const Upload u;
        u.write("lab1_first_image/gradient.cpp", std::string((1 << 20) + 1, 'x'));
        const SubmissionCopy copy = u.make();
        CHECK(u.copied().empty());
        CHECK_MESSAGE(listed(copy, "lab1_first_image/gradient.cpp: larger than 1048576 bytes"), copy.ignored.size());
    }
    SUBCASE("the copy's folder a link: it is replaced, its target untouched") {
        const Upload u;
        u.write("gradient.cpp", "// mine\n");
        fs::create_directories(u.root / "target");
        std::ofstream(u.root / "target/keep.txt") << "kept";
        fs::create_directory_symlink(u.root / "target", u.copy);
        u.make();
        CHECK(fs::is_directory(fs::symlink_status(u.copy)));
        CHECK(readFile(u.root / "target/keep.txt") == "kept");
    }
}
#endif

TEST_CASE("a name that is not UTF-8 or holds a control character is shown escaped") {
    const Upload u;
    u.write("lab3_sphere/bad\xfe\x1b[2Jname.cpp", "x");
    const SubmissionCopy copy = u.make();
    REQUIRE(copy.ignored.size() == 1);
    CHECK(copy.ignored[0].rfind("lab3_sphere/bad\\xFE\\x1B[2Jname.cpp: not a lab file", 0) == 0);
}

} // TEST_SUITE
