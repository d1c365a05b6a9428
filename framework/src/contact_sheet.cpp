#include "src/contact_sheet.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <stdexcept>

namespace raylab {

namespace {

// A 5 x 7 glyph: seven rows of five columns, '#' for ink.
struct Glyph {
    char c;
    std::array<const char*, 7> rows;
};

// clang-format off
constexpr Glyph kFont[] = {
    {'a', {".....", ".....", ".###.", "....#", ".####", "#...#", ".####"}},
    {'b', {"#....", "#....", "#.##.", "##..#", "#...#", "#...#", "####."}},
    {'c', {".....", ".....", ".###.", "#....", "#....", "#...#", ".###."}},
    {'d', {"....#", "....#", ".##.#", "#..##", "#...#", "#...#", ".####"}},
    {'e', {".....", ".....", ".###.", "#...#", "#####", "#....", ".###."}},
    {'f', {"..##.", ".#..#", ".#...", "###..", ".#...", ".#...", ".#..."}},
    {'g', {".....", ".####", "#...#", ".####", "....#", "#...#", ".###."}},
    {'h', {"#....", "#....", "#.##.", "##..#", "#...#", "#...#", "#...#"}},
    {'i', {"..#..", ".....", ".##..", "..#..", "..#..", "..#..", ".###."}},
    {'j', {"...#.", ".....", "..##.", "...#.", "...#.", "#..#.", ".##.."}},
    {'k', {"#....", "#....", "#..#.", "#.#..", "##...", "#.#..", "#..#."}},
    {'l', {".##..", "..#..", "..#..", "..#..", "..#..", "..#..", ".###."}},
    {'m', {".....", ".....", "##.#.", "#.#.#", "#.#.#", "#...#", "#...#"}},
    {'n', {".....", ".....", "#.##.", "##..#", "#...#", "#...#", "#...#"}},
    {'o', {".....", ".....", ".###.", "#...#", "#...#", "#...#", ".###."}},
    {'p', {".....", "####.", "#...#", "#...#", "####.", "#....", "#...."}},
    {'q', {".....", ".####", "#...#", "#...#", ".####", "....#", "....#"}},
    {'r', {".....", ".....", "#.##.", "##..#", "#....", "#....", "#...."}},
    {'s', {".....", ".....", ".####", "#....", ".###.", "....#", "####."}},
    {'t', {".#...", ".#...", "###..", ".#...", ".#...", ".#..#", "..##."}},
    {'u', {".....", ".....", "#...#", "#...#", "#...#", "#..##", ".##.#"}},
    {'v', {".....", ".....", "#...#", "#...#", "#...#", ".#.#.", "..#.."}},
    {'w', {".....", ".....", "#...#", "#...#", "#.#.#", "#.#.#", ".#.#."}},
    {'x', {".....", ".....", "#...#", ".#.#.", "..#..", ".#.#.", "#...#"}},
    {'y', {".....", ".....", "#...#", "#...#", ".####", "....#", ".###."}},
    {'z', {".....", ".....", "#####", "...#.", "..#..", ".#...", "#####"}},
    {'0', {".###.", "#...#", "#..##", "#.#.#", "##..#", "#...#", ".###."}},
    {'1', {"..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###."}},
    {'2', {".###.", "#...#", "....#", "...#.", "..#..", ".#...", "#####"}},
    {'3', {"#####", "...#.", "..#..", "...#.", "....#", "#...#", ".###."}},
    {'4', {"...#.", "..##.", ".#.#.", "#..#.", "#####", "...#.", "...#."}},
    {'5', {"#####", "#....", "####.", "....#", "....#", "#...#", ".###."}},
    {'6', {"..##.", ".#...", "#....", "####.", "#...#", "#...#", ".###."}},
    {'7', {"#####", "....#", "...#.", "..#..", ".#...", ".#...", ".#..."}},
    {'8', {".###.", "#...#", "#...#", ".###.", "#...#", "#...#", ".###."}},
    {'9', {".###.", "#...#", "#...#", ".####", "....#", "...#.", ".##.."}},
    {'_', {".....", ".....", ".....", ".....", ".....", ".....", "#####"}},
    {'-', {".....", ".....", ".....", "#####", ".....", ".....", "....."}},
    {'.', {".....", ".....", ".....", ".....", ".....", ".##..", ".##.."}},
    {'(', {"...#.", "..#..", ".#...", ".#...", ".#...", "..#..", "...#."}},
    {')', {".#...", "..#..", "...#.", "...#.", "...#.", "..#..", ".#..."}},
    {' ', {".....", ".....", ".....", ".....", ".....", ".....", "....."}},
};
constexpr Glyph kUnknown{'?', {"#####", "#...#", "#...#", "#...#", "#...#", "#...#", "#####"}};
// clang-format on

constexpr int kGlyphWidth = 5;
constexpr int kGlyphHeight = 7;
constexpr int kAdvance = kGlyphWidth + 1;

const Glyph& glyphOf(char c) {
    const char lower = char(std::tolower(static_cast<unsigned char>(c)));
    for (const Glyph& g : kFont)
        if (g.c == lower) return g;
    return kUnknown;
}

using Rgb = std::array<std::uint8_t, 3>;

void put(Image8& image, int x, int y, const Rgb& color) {
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
    std::uint8_t* p = &image.rgb[3 * (std::size_t(y) * std::size_t(image.width) + std::size_t(x))];
    p[0] = color[0];
    p[1] = color[1];
    p[2] = color[2];
}

void fillRect(Image8& image, int x0, int y0, int w, int h, const Rgb& color) {
    for (int y = y0; y < y0 + h; ++y)
        for (int x = x0; x < x0 + w; ++x) put(image, x, y, color);
}

void drawText(Image8& image, int x0, int y0, const std::string& text, int scale, const Rgb& color) {
    for (std::size_t k = 0; k < text.size(); ++k) {
        const Glyph& g = glyphOf(text[k]);
        const int gx = x0 + int(k) * kAdvance * scale;
        for (int row = 0; row < kGlyphHeight; ++row)
            for (int col = 0; col < kGlyphWidth; ++col)
                if (g.rows[std::size_t(row)][col] == '#') fillRect(image, gx + col * scale, y0 + row * scale, scale, scale, color);
    }
}

// The scale (2, else 1) at which `text` fits in `width` pixels.
int textScale(const std::string& text, int width) { return contactSheetTextWidth(text, 2) <= width ? 2 : 1; }

// Shrinks `src` by averaging, in linear 8-bit values, the source pixels whose centres fall in each
// destination pixel (a box filter); draws the result with its top-left corner at (x0, y0).
void drawThumbnail(Image8& sheet, int x0, int y0, const Image8& src, int w, int h) {
    const double fx = double(src.width) / w, fy = double(src.height) / h;
    for (int y = 0; y < h; ++y) {
        const int sy0 = int(std::ceil(y * fy - 0.5)), sy1 = std::max(sy0 + 1, int(std::ceil((y + 1) * fy - 0.5)));
        for (int x = 0; x < w; ++x) {
            const int sx0 = int(std::ceil(x * fx - 0.5)), sx1 = std::max(sx0 + 1, int(std::ceil((x + 1) * fx - 0.5)));
            unsigned sum[3] = {0, 0, 0};
            unsigned count = 0;
            for (int sy = std::max(sy0, 0); sy < std::min(sy1, src.height); ++sy)
                for (int sx = std::max(sx0, 0); sx < std::min(sx1, src.width); ++sx) {
                    const std::uint8_t* p = src.pixel(sx, sy);
                    for (int c = 0; c < 3; ++c) sum[c] += p[c];
                    ++count;
                }
            if (count == 0) continue;
            put(sheet, x0 + x, y0 + y,
                Rgb{std::uint8_t((sum[0] + count / 2) / count), std::uint8_t((sum[1] + count / 2) / count),
                    std::uint8_t((sum[2] + count / 2) / count)});
        }
    }
}

} // namespace

int contactSheetTextWidth(const std::string& text, int scale) {
    return text.empty() ? 0 : (int(text.size()) * kAdvance - 1) * scale;
}

Image8 makeContactSheet(const std::vector<ContactSheetItem>& items, const ContactSheetLayout& layout) {
    if (layout.columns < 1 || layout.thumbWidth < 1 || layout.thumbHeight < 1 || layout.margin < 0)
        throw std::invalid_argument("makeContactSheet: the layout needs at least 1 column and a thumbnail of 1 x 1");
    const Rgb paper{255, 255, 255}, ink{0, 0, 0}, empty{64, 64, 64}, emptyInk{255, 255, 255};
    const int labelHeight = 2 * kGlyphHeight + 6;
    const int columns = std::max(1, std::min(layout.columns, int(items.size())));
    const int rows = std::max(1, (int(items.size()) + columns - 1) / columns);
    const int cellWidth = layout.thumbWidth + layout.margin, cellHeight = layout.thumbHeight + labelHeight + layout.margin;

    Image8 sheet{layout.margin + columns * cellWidth, layout.margin + rows * cellHeight, {}};
    sheet.rgb.assign(std::size_t(sheet.width) * std::size_t(sheet.height) * 3, 255);
    fillRect(sheet, 0, 0, sheet.width, sheet.height, paper);

    for (std::size_t k = 0; k < items.size(); ++k) {
        const ContactSheetItem& item = items[k];
        const int x0 = layout.margin + int(k % std::size_t(columns)) * cellWidth;
        const int y0 = layout.margin + int(k / std::size_t(columns)) * cellHeight;
        if (item.image && item.image->width > 0 && item.image->height > 0) {
            // Fit inside the cell, keeping the aspect ratio; never enlarge.
            const Image8& img = *item.image;
            const double s = std::min({1.0, double(layout.thumbWidth) / img.width, double(layout.thumbHeight) / img.height});
            const int w = std::max(1, int(std::lround(img.width * s))), h = std::max(1, int(std::lround(img.height * s)));
            drawThumbnail(sheet, x0 + (layout.thumbWidth - w) / 2, y0 + (layout.thumbHeight - h) / 2, img, w, h);
        } else {
            fillRect(sheet, x0, y0, layout.thumbWidth, layout.thumbHeight, empty);
            const int scale = textScale(item.status, layout.thumbWidth);
            drawText(sheet, x0 + (layout.thumbWidth - contactSheetTextWidth(item.status, scale)) / 2,
                     y0 + (layout.thumbHeight - kGlyphHeight * scale) / 2, item.status, scale, emptyInk);
        }
        const int scale = textScale(item.id, layout.thumbWidth);
        drawText(sheet, x0 + (layout.thumbWidth - contactSheetTextWidth(item.id, scale)) / 2,
                 y0 + layout.thumbHeight + 3 + (2 - scale) * kGlyphHeight / 2, item.id, scale, ink);
    }
    return sheet;
}

} // namespace raylab
