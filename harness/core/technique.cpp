#include "core/technique.hpp"

namespace canopy {

const char* to_string(DepthFormat format) { return format == DepthFormat::d16 ? "d16" : "d32f"; }

const char* to_string(MomentFormat format) {
    switch (format) {
        case MomentFormat::r16f: return "r16f";
        case MomentFormat::r32f: return "r32f";
        case MomentFormat::rg16f: return "rg16f";
        case MomentFormat::rg32f: return "rg32f";
        case MomentFormat::rgba16f: return "rgba16f";
        case MomentFormat::rgba32f: return "rgba32f";
        case MomentFormat::rgba16unorm: return "rgba16unorm";
    }
    return "?";
}

uint32_t bytes_per_texel(MomentFormat format) {
    switch (format) {
        case MomentFormat::r16f: return 2;
        case MomentFormat::r32f: return 4;
        case MomentFormat::rg16f: return 4;
        case MomentFormat::rg32f: return 8;
        case MomentFormat::rgba16f: return 8;
        case MomentFormat::rgba32f: return 16;
        case MomentFormat::rgba16unorm: return 8;
    }
    return 0;
}

}  // namespace canopy
