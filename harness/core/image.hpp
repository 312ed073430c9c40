// A linear-light float RGBA image, row-major, top row first.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace canopy {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<float> pixels;  // width * height * 4, RGBA

    Image() = default;
    Image(int w, int h) : width(w), height(h), pixels(size_t(w) * size_t(h) * 4, 0.0f) {}
    float* at(int x, int y) { return &pixels[(size_t(y) * size_t(width) + size_t(x)) * 4]; }
    const float* at(int x, int y) const { return &pixels[(size_t(y) * size_t(width) + size_t(x)) * 4]; }
    // Sets pixel (x, y) to `rgb`, opaque (alpha 1).
    void set_opaque(int x, int y, const std::array<float, 3>& rgb) {
        float* p = at(x, y);
        p[0] = rgb[0];
        p[1] = rgb[1];
        p[2] = rgb[2];
        p[3] = 1.0f;
    }
    // Rec. 709 luminance of pixel (x, y).
    float luminance(int x, int y) const {
        const float* p = at(x, y);
        return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
    }
};

}  // namespace canopy
