#pragma once
// A contact sheet: every figure as a thumbnail, in order, with its id written under it.

#include "raylab/image_io.h"

#include <optional>
#include <string>
#include <vector>

namespace raylab {

struct ContactSheetItem {
    std::string id;              // written under the thumbnail
    std::optional<Image8> image; // none: the tile shows `status` instead (e.g. "todo")
    std::string status;
};

struct ContactSheetLayout {
    int columns = 4;
    int thumbWidth = 280;  // each image is shrunk (never enlarged) to fit thumbWidth x thumbHeight
    int thumbHeight = 187;
    int margin = 10;
};

// The ids and statuses are drawn with a built-in 5 x 7 pixel font: lower-case letters, digits,
// '_', '-', '.', '(', ')' and spaces (upper case is drawn as lower case; other characters as a box).
Image8 makeContactSheet(const std::vector<ContactSheetItem>& items, const ContactSheetLayout& layout = {});

// The width in pixels of `text` drawn at `scale` (6 * scale a character, without the last space).
int contactSheetTextWidth(const std::string& text, int scale);

} // namespace raylab
