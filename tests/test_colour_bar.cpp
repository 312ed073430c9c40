// Heat maps carry their scale: a colour bar beside the image, labelled in a built-in font.
#include "metrics/bitmap_font.hpp"
#include "metrics/colour_bar.hpp"
#include "metrics/error_maps.hpp"

#include <doctest/doctest.h>

#include <cstring>

using namespace canopy;

namespace {

bool same_rgb(const float* p, const ColormapEntry& c) { return p[0] == c[0] && p[1] == c[1] && p[2] == c[2]; }

// Whether `text` is drawn in white with its top-left corner at (x, y), on black.
bool text_at(const Image& image, int x, int y, const std::string& text) {
    for (size_t i = 0; i < text.size(); ++i)
        for (int row = 0; row < kGlyphHeight; ++row)
            for (int column = 0; column < kGlyphAdvance; ++column) {
                const float* p = image.at(x + int(i) * kGlyphAdvance + column, y + row);
                const bool lit = glyph_pixel(text[i], column, row);
                if (p[0] != (lit ? 1.0f : 0.0f) || p[1] != p[0] || p[2] != p[0]) return false;
            }
    return true;
}

}  // namespace

TEST_CASE("the font draws what it is asked to, and only there") {
    Image image(20, 10);
    draw_text(image, 1, 1, "0.5", {1, 1, 1});
    CHECK(text_at(image, 1, 1, "0.5"));
    CHECK_FALSE(text_at(image, 1, 1, "0.6"));
    CHECK(text_width("0.5") == 17);
    // Every glyph canopy labels with differs from every other one.
    const std::string chars = "0123456789.-+e";
    for (char a : chars)
        for (char b : chars) {
            if (a == b) continue;
            bool differ = false;
            for (int y = 0; y < kGlyphHeight; ++y)
                for (int x = 0; x < kGlyphWidth; ++x) differ |= glyph_pixel(a, x, y) != glyph_pixel(b, x, y);
            CHECK_MESSAGE(differ, a, " vs ", b);
        }
    draw_text(image, 18, 8, "8", {1, 0, 0});  // clipped at the edges, no crash
}

TEST_CASE("an error map gets its scale beside it: viridis from 0 at the bottom to the scale at the top") {
    Image test(96, 64), reference(96, 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 96; ++x) test.at(x, y)[1] = float(x) / 96.0f;
    const double scale = 0.275;
    const Image heatmap = absolute_error_heatmap(test, reference, scale);
    const Image out = with_colour_bar(heatmap, viridis_colormap(), scale);
    const ColourBarLayout l = colour_bar_layout(96, 64, scale);
    REQUIRE(out.width == l.width);
    REQUIRE(out.height == 64);
    CHECK(out.width > 96 + 20);
    // The heat map itself is unchanged.
    for (int y = 0; y < 64; ++y) CHECK(std::memcmp(out.at(0, y), heatmap.at(0, y), 96 * 4 * sizeof(float)) == 0);
    // The bar runs through the whole colour map, bottom to top.
    const int x = (l.bar_left + l.bar_right) / 2;
    CHECK(same_rgb(out.at(x, l.bar_bottom), viridis_colormap()[0]));
    CHECK(same_rgb(out.at(x, l.bar_top), viridis_colormap()[255]));
    const int middle = (l.bar_top + l.bar_bottom) / 2;
    const float fraction = float(l.bar_bottom - middle) / float(l.bar_bottom - l.bar_top);
    CHECK(fraction == doctest::Approx(0.5).epsilon(0.02));
    CHECK(same_rgb(out.at(x, middle), map_to_color(viridis_colormap(), fraction)));
    // Labels: the scale at the top, its half in the middle, 0 at the bottom.
    CHECK(colour_bar_label(scale) == "0.275");
    CHECK(text_at(out, l.label_left, l.bar_top - kGlyphHeight / 2, "0.275"));
    CHECK(text_at(out, l.label_left, (l.bar_top + l.bar_bottom) / 2 - kGlyphHeight / 2, colour_bar_label(scale / 2)));
    CHECK(text_at(out, l.label_left, l.bar_bottom - kGlyphHeight / 2, "0"));
}

TEST_CASE("small maps grow to fit the labels; FLIP maps read 0 to 1") {
    const Image heatmap = flip_heatmap(std::vector<float>(16 * 8, 0.25f), 16, 8);
    const Image out = with_colour_bar(heatmap, magma_colormap(), 1.0);
    const ColourBarLayout l = colour_bar_layout(16, 8, 1.0);
    CHECK(out.height == 32);
    CHECK(text_at(out, l.label_left, l.bar_top - kGlyphHeight / 2, "1"));
    CHECK(text_at(out, l.label_left, l.bar_bottom - kGlyphHeight / 2, "0"));
    CHECK(same_rgb(out.at(l.bar_left, l.bar_top), magma_colormap()[255]));
    CHECK(colour_bar_label(6.25e-05) == "6.25e-05");
}
