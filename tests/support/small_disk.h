#pragma once
// A small file system the tests can fill (Linux, as root): a tmpfs of a few megabytes mounted on a
// folder, so that a full disk is a real ENOSPC from the kernel, not a simulation. Where mount is not
// permitted (not root, a container without CAP_SYS_ADMIN), `why` says so and the test skips.

#ifdef __linux__

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>
#include <sys/mount.h>

namespace raylab::test {

class SmallDisk {
public:
    SmallDisk(const std::filesystem::path& folder, int megabytes) : m_folder(folder) {
        std::filesystem::create_directories(folder);
        m_mounted = ::mount("tmpfs", folder.c_str(), "tmpfs", 0, size(megabytes).c_str()) == 0;
        if (!m_mounted) why = "cannot mount a tmpfs on " + folder.string() + ": " + std::strerror(errno);
    }
    ~SmallDisk() {
        if (m_mounted) ::umount2(m_folder.c_str(), MNT_DETACH);
    }
    SmallDisk(const SmallDisk&) = delete;
    SmallDisk& operator=(const SmallDisk&) = delete;

    bool mounted() const { return m_mounted; }
    // Room made (or taken) without losing a file: the tmpfs's new size.
    bool resize(int megabytes) { return ::mount("tmpfs", m_folder.c_str(), "tmpfs", MS_REMOUNT, size(megabytes).c_str()) == 0; }

    std::string why; // when not mounted

private:
    static std::string size(int megabytes) { return "size=" + std::to_string(megabytes) + "m"; }
    std::filesystem::path m_folder;
    bool m_mounted = false;
};

} // namespace raylab::test

#endif
