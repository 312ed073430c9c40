#include "metrics/colour_bar.hpp"

#include "metrics/bitmap_font.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>

namespace canopy {

namespace {

constexpr int kGap = 4, kBarWidth = 10, kLabelGap = 3, kMargin = 3;
constexpr int kMinHeight = 32;     // room for two labels
constexpr int kMiddleLabelFrom = 48;  // room for three

}  // namespace

std::string colour_bar_label(double value) { return value == 0.0 ? "0" : fmt::format("{:.3g}", value); }

ColourBarLayout colour_bar_layout(int width, int height, double max_value) {
    ColourBarLayout l;
    l.height = std::max(height, kMinHeight);
    l.bar_left = width + kGap;
    l.bar_right = l.bar_left + kBarWidth - 1;
    l.bar_top = kGlyphHeight / 2 + 1;
    l.bar_bottom = l.height - 1 - (kGlyphHeight / 2 + 1);
    l.label_left = l.bar_right + 1 + kLabelGap;
    const int labels = std::max(text_width(colour_bar_label(max_value)), text_width(colour_bar_label(max_value / 2.0)));
    l.width = l.label_left + labels + kMargin;
    return l;
}

Image with_colour_bar(const Image& heatmap, const std::array<ColormapEntry, 256>& colormap, double max_value) {
    const std::string top = colour_bar_label(max_value), middle = colour_bar_label(max_value / 2.0);
    const ColourBarLayout l = colour_bar_layout(heatmap.width, heatmap.height, max_value);
    Image out(l.width, l.height);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) out.at(x, y)[3] = 1.0f;  // black, opaque
    for (int y = 0; y < heatmap.height; ++y)
        std::memcpy(out.at(0, y), heatmap.at(0, y), size_t(heatmap.width) * 4 * sizeof(float));

    // A grey frame, so the dark end of magma stays visible on the black panel.
    const std::array<float, 3> grey = {0.5f, 0.5f, 0.5f};
    for (int y = l.bar_top - 1; y <= l.bar_bottom + 1; ++y)
        for (int x = l.bar_left - 1; x <= l.bar_right + 1; ++x) out.set_opaque(x, y, grey);
    const int span = l.bar_bottom - l.bar_top;
    for (int y = l.bar_top; y <= l.bar_bottom; ++y) {
        const ColormapEntry colour = map_to_color(colormap, float(double(l.bar_bottom - y) / double(span)));
        for (int x = l.bar_left; x <= l.bar_right; ++x) out.set_opaque(x, y, colour);
    }
    const std::array<float, 3> white = {1.0f, 1.0f, 1.0f};
    auto label = [&](int tick_y, const std::string& text) {
        draw_text(out, l.label_left, std::clamp(tick_y - kGlyphHeight / 2, 0, l.height - kGlyphHeight), text, white);
    };
    label(l.bar_top, top);
    label(l.bar_bottom, "0");
    if (l.height >= kMiddleLabelFrom) label((l.bar_top + l.bar_bottom) / 2, middle);
    return out;
}

}  // namespace canopy
