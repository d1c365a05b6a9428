// One holder at a time (src/file_lock.h): a second lock of the same file is refused while the first
// is held, names its holder, and is taken once the first is released, by its destruction or by
// waiting for it.
#include "support/files.h"
#include "src/file_lock.h"

#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <string>
#include <thread>
#ifdef _WIN32
#include <process.h>
#define RAYLAB_TEST_PID _getpid()
#else
#include <unistd.h>
#define RAYLAB_TEST_PID getpid()
#endif

namespace fs = std::filesystem;

TEST_SUITE("file lock") {
TEST_CASE("a held lock is refused to another holder, which is told whose it is, and taken once released") {
    const fs::path folder = raylab::test::freshFolder("file-lock");
    const fs::path file = folder / "build.lock";
    auto first = std::make_unique<raylab::FileLock>(file);
    raylab::FileLock second(file);
    CHECK(second.holder().empty()); // nobody wrote it yet
    REQUIRE(first->tryAcquire());
    CHECK_FALSE(second.tryAcquire());
    CHECK(second.holder() == std::to_string(RAYLAB_TEST_PID));
    first.reset(); // released with its holder
    CHECK(second.tryAcquire());
}

TEST_CASE("acquire waits for the holder to release it") {
    const fs::path file = raylab::test::freshFolder("file-lock-wait") / "build.lock";
    auto first = std::make_unique<raylab::FileLock>(file);
    REQUIRE(first->tryAcquire());
    std::atomic<bool> released = false;
    std::thread holder([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        released = true;
        first.reset();
    });
    raylab::FileLock second(file);
    CHECK(second.acquire());
    CHECK(released); // it did wait for the release
    holder.join();
}

TEST_CASE("a lock whose file cannot be made is an error that names it") {
    const fs::path file = raylab::test::freshFolder("file-lock-missing") / "no such folder" / "build.lock";
    try {
        raylab::FileLock lock(file);
        FAIL("no error");
    } catch (const std::runtime_error& e) {
        CHECK(std::string(e.what()).find("no such folder") != std::string::npos);
    }
}
}
