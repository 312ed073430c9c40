#include "metrics/bitmap_font.hpp"

#include <cstdint>

namespace canopy {

namespace {

// 7 rows of 5 bits, most significant of the 5 on the left.
using Glyph = std::array<uint8_t, kGlyphHeight>;

const Glyph* glyph(char c) {
    static const Glyph digits[10] = {
        {0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E},  // 0
        {0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E},  // 1
        {0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F},  // 2
        {0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E},  // 3
        {0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02},  // 4
        {0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E},  // 5
        {0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E},  // 6
        {0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08},  // 7
        {0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E},  // 8
        {0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C},  // 9
    };
    static const Glyph dot = {0x00, 0x00, 0x00, 0x00, 0x00, 0x0C, 0x0C};
    static const Glyph minus = {0x00, 0x00, 0x00, 0x1F, 0x00, 0x00, 0x00};
    static const Glyph plus = {0x00, 0x04, 0x04, 0x1F, 0x04, 0x04, 0x00};
    static const Glyph e = {0x00, 0x00, 0x0E, 0x11, 0x1F, 0x10, 0x0E};
    static const Glyph space = {0, 0, 0, 0, 0, 0, 0};
    static const Glyph unknown = {0x1F, 0x1F, 0x1F, 0x1F, 0x1F, 0x1F, 0x1F};
    if (c >= '0' && c <= '9') return &digits[c - '0'];
    switch (c) {
        case '.': return &dot;
        case '-': return &minus;
        case '+': return &plus;
        case 'e':
        case 'E': return &e;
        case ' ': return &space;
        default: return &unknown;
    }
}

}  // namespace

int text_width(std::string_view text) { return text.empty() ? 0 : int(text.size()) * kGlyphAdvance - 1; }

bool glyph_pixel(char c, int x, int y) {
    if (x < 0 || x >= kGlyphWidth || y < 0 || y >= kGlyphHeight) return false;
    return ((*glyph(c))[size_t(y)] >> (kGlyphWidth - 1 - x)) & 1u;
}

void draw_text(Image& image, int x, int y, std::string_view text, const std::array<float, 3>& rgb) {
    for (size_t i = 0; i < text.size(); ++i) {
        const int left = x + int(i) * kGlyphAdvance;
        for (int row = 0; row < kGlyphHeight; ++row)
            for (int column = 0; column < kGlyphWidth; ++column) {
                const int px = left + column, py = y + row;
                if (px < 0 || py < 0 || px >= image.width || py >= image.height || !glyph_pixel(text[i], column, row)) continue;
                image.set_opaque(px, py, rgb);
            }
    }
}

}  // namespace canopy
