#include "metrics/coverage_error.hpp"

#include "core/pixel_visibility.hpp"
#include "metrics/comparable_pair.hpp"

#include <cmath>
#include <limits>

namespace canopy {

CoverageError compute_coverage_error(const Image& technique, const Image& reference) {
    require_same_size(technique, reference, "compute_coverage_error");
    const int channel = pixel_visibility::kCoverage;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const int tiles_x = (technique.width + kCoverageTile - 1) / kCoverageTile;
    const int tiles_y = (technique.height + kCoverageTile - 1) / kCoverageTile;
    struct Tile {
        double test = 0, truth = 0;
        long long pixels = 0;
        bool covered = false;
    };
    std::vector<Tile> tiles(size_t(tiles_x) * size_t(tiles_y));

    double abs_sum = 0, test_sum = 0, truth_sum = 0;
    long long covered = 0;
    for (int y = 0; y < technique.height; ++y)
        for (int x = 0; x < technique.width; ++x) {
            const double t = technique.at(x, y)[channel];
            const double r = reference.at(x, y)[channel];
            if (!std::isfinite(t) || !std::isfinite(r)) continue;
            Tile& tile = tiles[size_t(y / kCoverageTile) * size_t(tiles_x) + size_t(x / kCoverageTile)];
            tile.test += t;
            tile.truth += r;
            ++tile.pixels;
            test_sum += t;
            truth_sum += r;
            if (t > 0 || r > 0) {
                tile.covered = true;
                ++covered;
                abs_sum += std::abs(t - r);
            }
        }

    CoverageError error{nan, nan, nan, nan, covered};
    if (covered == 0) return error;
    error.mae = abs_sum / double(covered);
    double tile_sum = 0;
    long long tile_count = 0;
    for (const Tile& tile : tiles) {
        if (!tile.covered) continue;
        tile_sum += std::abs(tile.test - tile.truth) / double(tile.pixels);
        ++tile_count;
    }
    error.tile_mae = tile_sum / double(tile_count);
    if (truth_sum > 0) {
        error.total_error = std::abs(test_sum - truth_sum) / truth_sum;
        error.bias = test_sum / truth_sum - 1.0;
    }
    return error;
}

}  // namespace canopy
