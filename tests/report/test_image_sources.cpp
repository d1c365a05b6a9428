// report.html shows, and report.pdf embeds, only images from the kit's folder and the tree's out/:
// every way of writing an address that reaches another file is refused, and a file inside is shown
// whichever way its address is written. These run on paths alone (no render).
#include "support/files.h"
#include <doctest/doctest.h>

#include "report/image_sources.h"

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace fs = std::filesystem;
using raylab::report::imageAllowed;
using raylab::report::ImageSources;

namespace {

// tree/out/report-kit/ (the kit, with figures/a.png), tree/out/student/b.png, tree/secret.png beside
// out/, and the kit's link/ leading to tree/ (where a file system has symbolic links).
struct Tree {
    fs::path root = raylab::test::freshFolder("raylab-report-images");
    fs::path out = root / "out", kit = out / "report-kit";
    ImageSources sources{kit / "report.html", {kit, out}};
    bool linked = false;

    Tree() {
        fs::create_directories(kit / "figures");
        fs::create_directories(out / "student");
        for (const fs::path& file : {kit / "figures" / "a.png", out / "student" / "b.png", root / "secret.png"})
            std::ofstream(file) << "png";
        std::error_code error;
        fs::create_directory_symlink(root, kit / "link", error);
        linked = !error;
    }
};

} // namespace

TEST_SUITE("report") {

TEST_CASE("report images: a file in the kit or in out/ is shown, however its address is written") {
    const Tree tree;
    for (const std::string address : {"figures/a.png", "./figures/a.png", "figures/../figures/a.png", "figures/a.png?v=2#top",
                                      "figures%2Fa.png", "figures\\a.png", "../student/b.png", "%2e%2e/student/b.png",
                                      "missing.png" /* inside, even before it is made */})
        CHECK_MESSAGE(imageAllowed(address, tree.sources), address);
    CHECK(imageAllowed((tree.kit / "figures" / "a.png").string(), tree.sources)); // an absolute path inside
}

TEST_CASE("report images: an address that leaves the allowed folders is refused") {
    const Tree tree;
    const std::string secret = (tree.root / "secret.png").string();
    for (const std::string& address : {secret, std::string("../../secret.png"), std::string("%2e%2e/%2E%2E/secret.png"),
                                      std::string("..\\..\\secret.png"), std::string("../student/../../secret.png"),
                                      std::string("file://") + secret, std::string("FILE:") + secret,
                                      std::string("http://example.com/a.png"), std::string("https://example.com/a.png"),
                                      std::string("data:image/png;base64,iVBORw0KGgo="), std::string("//example.com/a.png"),
                                      std::string("C:/Windows/a.png"), std::string("/etc/passwd"), std::string(""),
                                      std::string("figures/a.png%00.txt"), std::string("?x"), std::string("#top")})
        CHECK_MESSAGE(!imageAllowed(address, tree.sources), address);
    if (tree.linked) CHECK(!imageAllowed("link/secret.png", tree.sources)); // a link out of the kit is followed
}

TEST_CASE("report images: nothing is allowed when no folder is") {
    const Tree tree;
    CHECK(!imageAllowed("figures/a.png", ImageSources{tree.kit / "report.html", {}}));
}

} // TEST_SUITE
