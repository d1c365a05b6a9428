// Files written whole or not at all (raylab/atomic_file.h): a failed write names the file and the
// reason, leaves the old file as it was and no temporary file behind.
#include "support/files.h"
#include "src/atomic_file.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>
#if defined(__unix__) || defined(__APPLE__)
#include <csignal>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

namespace fs = std::filesystem;

namespace {

using raylab::test::freshFolder;
using raylab::test::readFile;

std::vector<std::string> entries(const fs::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// The message of the WriteError that `write` throws; fails the test when it throws none.
template <class Write> std::string writeError(Write write) {
    try {
        write();
    } catch (const raylab::WriteError& e) {
        return e.what();
    }
    FAIL("no WriteError");
    return "";
}

} // namespace

TEST_SUITE("atomic files") {

TEST_CASE("a file is written whole, replaces the old one, and leaves nothing else in its folder") {
    const fs::path folder = freshFolder("raylab-atomic");
    raylab::writeFileAtomically(folder / "sub" / "a.txt", "first");
    CHECK(readFile(folder / "sub" / "a.txt") == "first");
    const std::string big(3 << 20, 'x'); // more than one write() may take
    raylab::writeFileAtomically(folder / "sub" / "a.txt", big);
    CHECK(readFile(folder / "sub" / "a.txt") == big);
    CHECK(entries(folder / "sub") == std::vector<std::string>{"a.txt"});
    fs::remove_all(folder);
}

TEST_CASE("a file is read whole, every byte (NUL, CR, beyond one buffer); a missing file or a folder reads nothing") {
    const fs::path folder = freshFolder("raylab-read-whole");
    std::string bytes(200000, 'a'); // more than the 64 KB read at a time
    bytes[7] = '\0';
    bytes[100] = '\r';
    bytes.back() = '\n';
    raylab::writeFileAtomically(folder / "data.bin", bytes);
    CHECK(raylab::readWholeFile(folder / "data.bin") == bytes);
    raylab::writeFileAtomically(folder / "empty.txt", "");
    CHECK(raylab::readWholeFile(folder / "empty.txt") == std::string());
    CHECK_FALSE(raylab::readWholeFile(folder / "absent.txt"));
    CHECK_FALSE(raylab::readWholeFile(folder));
    fs::remove_all(folder);
}

TEST_CASE("a folder in the way, or a file where a folder should be, is an error naming the file") {
    const fs::path folder = freshFolder("raylab-atomic-notdir");
    std::ofstream(folder / "a_regular_file") << "old";
    const std::string below = writeError([&] { raylab::writeFileAtomically(folder / "a_regular_file" / "x.png", "new"); });
    CHECK_MESSAGE(below.find((folder / "a_regular_file" / "x.png").string()) != std::string::npos, below);
    CHECK(readFile(folder / "a_regular_file") == "old");
    fs::create_directories(folder / "dir");
    const std::string onFolder = writeError([&] { raylab::writeFileAtomically(folder / "dir", "new"); });
    CHECK_MESSAGE(onFolder.find("is a folder") != std::string::npos, onFolder);
    fs::remove_all(folder);
}

TEST_CASE("a symbolic link is followed: the file it names is replaced, the link stays") {
    const fs::path folder = freshFolder("raylab-atomic-link");
    std::ofstream(folder / "real.txt") << "old";
    fs::create_symlink("real.txt", folder / "link.txt");
    raylab::writeFileAtomically(folder / "link.txt", "new");
    CHECK(fs::is_symlink(folder / "link.txt"));
    CHECK(readFile(folder / "real.txt") == "new");
    fs::remove_all(folder);
}

#if defined(__unix__) || defined(__APPLE__)

#ifdef __linux__
TEST_CASE("a full device: the write error is reported with the file and the reason") {
    const std::string message = writeError([] { raylab::writeFileAtomically("/dev/full", std::string(100000, 'x')); });
    CHECK_MESSAGE(message.find("/dev/full") != std::string::npos, message);
    CHECK_MESSAGE(message.find("No space left on device") != std::string::npos, message);
    CHECK(fs::is_character_file("/dev/full")); // written in place, never replaced by a file
}

TEST_CASE("a folder nobody may create files in (/proc) is an error naming the file") {
    const std::string message = writeError([] { raylab::writeFileAtomically("/proc/raylab-test.png", "x"); });
    CHECK_MESSAGE(message.find("/proc/raylab-test.png") != std::string::npos, message);
}
#endif

TEST_CASE("a pipe nobody reads is refused at once instead of blocking, as a copy's source too") {
    const fs::path folder = freshFolder("raylab-atomic-fifo");
    REQUIRE(mkfifo((folder / "lab4_d.png").c_str(), 0600) == 0);
    const std::string message = writeError([&] { raylab::writeFileAtomically(folder / "lab4_d.png", "x"); });
    CHECK_MESSAGE(message.find("lab4_d.png") != std::string::npos, message);
    CHECK_THROWS_WITH(raylab::copyFileAtomically(folder / "lab4_d.png", folder / "copy.png"),
                      doctest::Contains("lab4_d.png: not a regular file"));
    raylab::writeFileAtomically(folder / "a.png", "picture");
    raylab::copyFileAtomically(folder / "a.png", folder / "report" / "a.png");
    CHECK(readFile(folder / "report" / "a.png") == "picture");
    fs::remove_all(folder);
}

TEST_CASE("a write cut short (the file size limit) leaves the old file whole and no temporary file") {
    const fs::path folder = freshFolder("raylab-atomic-limit");
    raylab::writeFileAtomically(folder / "report.md", "the old report");
    rlimit old{};
    REQUIRE(getrlimit(RLIMIT_FSIZE, &old) == 0);
    const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN); // so that write() fails with EFBIG
    rlimit small = old;
    small.rlim_cur = 4096;
    REQUIRE(setrlimit(RLIMIT_FSIZE, &small) == 0);
    std::string message;
    try {
        raylab::writeFileAtomically(folder / "report.md", std::string(100000, 'y'));
    } catch (const raylab::WriteError& e) {
        message = e.what();
    }
    setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, oldHandler);
    CHECK_MESSAGE(message.find((folder / "report.md").string()) != std::string::npos, message);
    CHECK_MESSAGE(message.find("File too large") != std::string::npos, message);
    CHECK(readFile(folder / "report.md") == "the old report");
    CHECK(entries(folder) == std::vector<std::string>{"report.md"});
    fs::remove_all(folder);
}

TEST_CASE("a read-only folder: an error naming the file, the old file intact") {
    if (geteuid() == 0) {
        MESSAGE("skipped: root writes into read-only folders (the other cases cover a folder that refuses)");
        return;
    }
    const fs::path folder = freshFolder("raylab-atomic-readonly");
    raylab::writeFileAtomically(folder / "report.md", "the old report");
    fs::permissions(folder, fs::perms::owner_read | fs::perms::owner_exec);
    const std::string message = writeError([&] { raylab::writeFileAtomically(folder / "report.md", "new"); });
    fs::permissions(folder, fs::perms::owner_all);
    CHECK_MESSAGE(message.find("Permission denied") != std::string::npos, message);
    CHECK(readFile(folder / "report.md") == "the old report");
    fs::remove_all(folder);
}

#endif

} // TEST_SUITE
