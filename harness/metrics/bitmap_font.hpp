// A tiny built-in 5x7 pixel font for labelling images (heat-map scales), so no font library or
// font file is needed. It draws digits, '.', '-', '+', 'e', 'E' and space; other characters
// are drawn as a filled box so a missing glyph is visible.
#pragma once

#include "core/image.hpp"

#include <array>
#include <string_view>

namespace canopy {

inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphHeight = 7;
inline constexpr int kGlyphAdvance = kGlyphWidth + 1;  // one column between characters

// Width in pixels of `text` drawn with draw_text.
int text_width(std::string_view text);

// Whether the glyph of `c` has its pixel (column x, row y) set; row 0 is the top.
bool glyph_pixel(char c, int x, int y);

// Draws `text` with its top-left corner at (x, y), setting covered pixels to `rgb` (alpha 1);
// pixels outside the image are skipped.
void draw_text(Image& image, int x, int y, std::string_view text, const std::array<float, 3>& rgb);

}  // namespace canopy
