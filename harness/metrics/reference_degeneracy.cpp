#include "metrics/reference_degeneracy.hpp"

#include <algorithm>
#include <cmath>

namespace canopy {

std::vector<std::string> degenerate_reference(const Image& radiance, const Image& visibility, ReferenceLighting lighting) {
    std::vector<std::string> reasons;
    float lowest = INFINITY, highest = -INFINITY;
    for (int y = 0; y < radiance.height; ++y)
        for (int x = 0; x < radiance.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const float v = radiance.at(x, y)[c];
                lowest = std::min(lowest, v);
                highest = std::max(highest, v);
            }
    if (radiance.width * radiance.height > 0 && highest - lowest <= 1e-6f * std::max(1.0f, std::abs(highest)))
        reasons.emplace_back("uniform image");

    const bool has_visibility = visibility.width == radiance.width && visibility.height == radiance.height &&
                                visibility.width * visibility.height > 0;
    if (!lighting.shadow_light || !has_visibility) return reasons;
    // Pixel-sample means: a penumbra is any fraction strictly between these bounds.
    constexpr float kNone = 1e-4f, kAll = 1.0f - 1e-4f;
    bool lit = false, penumbra = false;
    for (int y = 0; y < visibility.height; ++y)
        for (int x = 0; x < visibility.width; ++x) {
            const float fraction = visibility.at(x, y)[0];
            if (!(fraction > kNone)) continue;
            lit = true;
            penumbra = penumbra || (visibility.at(x, y)[1] > 0.5f && fraction < kAll);
        }
    if (!lit) reasons.emplace_back("no lit pixels");
    else if (lighting.area_light && !penumbra) reasons.emplace_back("no penumbra");
    return reasons;
}

std::string degenerate_reference_text(const std::vector<std::string>& reasons) {
    if (reasons.empty()) return "";
    std::string text = "degenerate reference: ";
    for (size_t i = 0; i < reasons.size(); ++i) text += (i ? ", " : "") + reasons[i];
    return text;
}

}  // namespace canopy
