#include "mip_chain.hpp"

#include "../shaders/mip_filters.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace canopy::grass {

const char* to_string(MipFilter filter) {
    switch (filter) {
        case MipFilter::box: return "box";
        case MipFilter::max_alpha: return "max-alpha";
        case MipFilter::coverage: return "coverage-preserving";
    }
    return "?";
}

double alpha_coverage(const RgbaLevel& level, float a_r) {
    if (level.texels.empty()) return 0.0;
    size_t kept = 0;
    for (const glm::vec4& t : level.texels) kept += t.w > a_r;
    return double(kept) / double(level.texels.size());
}

float coverage_reference(const RgbaLevel& level, double coverage) {
    std::vector<float> alphas;
    alphas.reserve(level.texels.size());
    for (const glm::vec4& t : level.texels) alphas.push_back(t.w);
    std::sort(alphas.begin(), alphas.end(), std::greater<float>());
    const size_t n = alphas.size();
    if (n == 0) return 0.0f;
    const size_t k = size_t(std::llround(std::clamp(coverage, 0.0, 1.0) * double(n)));
    if (k == 0) return alphas.front();  // nothing strictly above the largest
    // Keep the k largest, and every texel tied with the k-th: below it, halfway to the next
    // smaller alpha (0 where none is smaller or the k-th is 0 itself, which never passes).
    const float kth = alphas[k - 1];
    const auto smaller = std::upper_bound(alphas.begin(), alphas.end(), kth, std::greater<float>());
    return smaller == alphas.end() ? 0.5f * kth : 0.5f * (kth + *smaller);
}

RgbaLevel reduce(const RgbaLevel& level, MipFilter filter) {
    if (level.texels.size() != size_t(level.width) * level.height || level.texels.empty())
        throw std::invalid_argument("reduce: a level needs width x height texels");
    RgbaLevel next;
    next.width = std::max(1u, level.width / 2);
    next.height = std::max(1u, level.height / 2);
    next.texels.resize(size_t(next.width) * next.height);
    for (uint32_t y = 0; y < next.height; ++y)
        for (uint32_t x = 0; x < next.width; ++x) {
            const uint32_t x0 = std::min(2 * x, level.width - 1), x1 = std::min(2 * x + 1, level.width - 1);
            const uint32_t y0 = std::min(2 * y, level.height - 1), y1 = std::min(2 * y + 1, level.height - 1);
            const glm::vec4 &a = level.at(x0, y0), &b = level.at(x1, y0), &c = level.at(x0, y1), &d = level.at(x1, y1);
            next.texels[size_t(y) * next.width + x] =
                filter == MipFilter::box ? shader::mip_box(a, b, c, d) : shader::mip_max_alpha(a, b, c, d);
        }
    return next;
}

RgbaLevel resolve_supersampled(const RgbaLevel& fine, uint32_t factor) {
    if (factor == 0 || (factor & (factor - 1)) != 0)
        throw std::invalid_argument("resolve_supersampled: the factor must be a power of 2");
    RgbaLevel level = fine;
    for (uint32_t f = factor; f > 1; f /= 2) {
        const RgbaLevel mean = reduce(level, MipFilter::box), weighted = reduce(level, MipFilter::max_alpha);
        level = mean;
        for (size_t i = 0; i < level.texels.size(); ++i)
            level.texels[i] = glm::vec4(glm::vec3(weighted.texels[i]), mean.texels[i].w);
    }
    return level;
}

std::vector<RgbaLevel> mip_chain(const RgbaLevel& base, MipFilter filter, float a_r, bool bleed) {
    std::vector<RgbaLevel> chain{base};
    const double base_coverage = alpha_coverage(base, a_r);
    while (chain.back().width > 1 || chain.back().height > 1) {
        RgbaLevel next = reduce(chain.back(), filter);
        if (filter == MipFilter::coverage) {
            // Eq 4.13-4.15: a'_r keeps base_coverage of this level; scale = a_r / a'_r.
            const float reference = coverage_reference(next, base_coverage);
            const float scale = a_r / std::max(reference, 1e-6f);
            for (glm::vec4& t : next.texels) t = shader::mip_scale_alpha(t, scale);
        }
        chain.push_back(std::move(next));
    }
    if (bleed)
        for (size_t l = chain.size() - 1; l-- > 0;) {
            RgbaLevel& level = chain[l];
            const RgbaLevel& next = chain[l + 1];
            for (uint32_t y = 0; y < level.height; ++y)
                for (uint32_t x = 0; x < level.width; ++x) {
                    glm::vec4& t = level.texels[size_t(y) * level.width + x];
                    t = shader::mip_bleed(t, next.at(std::min(x / 2, next.width - 1), std::min(y / 2, next.height - 1)));
                }
        }
    return chain;
}

}  // namespace canopy::grass
