// A heat map's scale drawn beside it, so a PNG can be read without its JSON: a vertical bar of the
// colour map from 0 (bottom) to the map's maximum (top; larger values are drawn in the top
// colour), labelled with the values at its ends and middle in a built-in bitmap font.
#pragma once

#include "core/image.hpp"
#include "metrics/colormaps.hpp"

#include <string>

namespace canopy {

struct ColourBarLayout {
    int bar_left = 0, bar_right = 0;  // columns of the bar, inclusive
    int bar_top = 0, bar_bottom = 0;  // rows: max_value at bar_top, 0 at bar_bottom
    int label_left = 0;               // where the labels start
    int width = 0, height = 0;        // of the whole image
};

// Where the bar and labels go beside a heat map of `width` x `height` whose scale ends at `max_value`.
ColourBarLayout colour_bar_layout(int width, int height, double max_value);

// "0.0623": how a scale value is labelled.
std::string colour_bar_label(double value);

// The heat map (display-encoded, as error_maps.hpp returns) with a black panel on its right that
// holds the bar and its labels (white). The result is at least 32 pixels high; the heat map is
// copied unchanged into its top-left corner.
Image with_colour_bar(const Image& heatmap, const std::array<ColormapEntry, 256>& colormap, double max_value);

}  // namespace canopy
