// Hostile: a wrong gradient (red and green swapped), and an atexit handler that copies the
// reference picture (named by RAYLAB_HOSTILE_PNG) over every lab1_gradient.png it can reach
// after the figure was rendered: the folder it runs in, its parent and their subfolders.
#include "raylab/gradient.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace raylab {

namespace {

void overwritePictures() {
    const char* source = std::getenv("RAYLAB_HOSTILE_PNG");
    if (!source) return;
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::path here = fs::current_path(error);
    for (const fs::path& root : {here, here.parent_path()}) {
        fs::copy_file(source, root / "figures" / "lab1_gradient.png", fs::copy_options::overwrite_existing, error);
        for (fs::recursive_directory_iterator it(root, error), end; it != end; it.increment(error))
            if (it->path().filename() == "lab1_gradient.png")
                fs::copy_file(source, it->path(), fs::copy_options::overwrite_existing, error);
    }
}

const bool g_registered = [] { return std::atexit(overwritePictures) == 0; }();

} // namespace

void fillGradient(Texture& texture) {
    const int w = texture.width(), h = texture.height();
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) // bad: red and green swapped
            texture.setPixel(i, j, Color(h > 1 ? float(j) / float(h - 1) : 0.f, w > 1 ? float(i) / float(w - 1) : 0.f, 0.f));
}

} // namespace raylab
