#pragma once
// Which images report.html may show. Chromium prints into report.pdf whatever the page shows, so an
// image the student's text names from elsewhere (`/home/someone/secret.png`, `../../`, a web address)
// would be embedded in a document that is handed in: only files inside the kit's folder or the tree's
// out/ are shown; the others are left out of the page and named in the console.

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::report {

struct ImageSources {
    std::filesystem::path page;                 // report.html: relative addresses start from its folder
    std::vector<std::filesystem::path> allowed; // the folders images may come from
};

// Whether the image at `address` (as written in Markdown) is a file inside one of the allowed folders:
// no scheme (`file:`, `http:`...), no network path (`//host`); percent escapes decoded and `\` read as
// `/`, as a browser does; `..` and symbolic links resolved before the comparison.
bool imageAllowed(const std::string& address, const ImageSources& sources);

} // namespace raylab::report
