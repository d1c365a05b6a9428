#pragma once
// The figures' scene files of the tree's labs, each in its lab's folder: labs/<lab>/scenes/<id>.toml.

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::test {

inline const std::filesystem::path kLabsDir = RAYLAB_LABS_DIR;

// Every scene file of the labs' scenes/ folders.
inline std::vector<std::filesystem::path> labSceneFiles() {
    std::vector<std::filesystem::path> files;
    for (const auto& lab : std::filesystem::directory_iterator(kLabsDir)) {
        std::error_code error;
        for (const auto& entry : std::filesystem::directory_iterator(lab.path() / "scenes", error))
            if (entry.path().extension() == ".toml") files.push_back(entry.path());
    }
    return files;
}

// The scene file of figure `id`, whichever lab's it is (an empty path when no lab has it).
inline std::filesystem::path figureSceneFile(const std::string& id) {
    for (const std::filesystem::path& file : labSceneFiles())
        if (file.stem() == id) return file;
    return {};
}

} // namespace raylab::test
