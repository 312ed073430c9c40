#include "timing_only/timing_only.hpp"

#include <stdexcept>

namespace canopy {

void throw_timing_only(const std::string& what) {
    throw std::logic_error(what + " is not in this timing-only canopy (built with CANOPY_TIMING_ONLY, without "
                           "image-file libraries and Embree); main() should have refused the command");
}

std::optional<std::string> timing_only_refusal(bool timing_only_build, bool wants_reference, bool writes_images) {
    if (!timing_only_build || (!wants_reference && !writes_images)) return std::nullopt;
    std::string lacks, add;
    if (wants_reference) {
        lacks = "ray-trace references (no Embree)";
        add = "--no-reference";
    }
    if (writes_images) {
        lacks += std::string(lacks.empty() ? "" : " or ") + "write images (no OpenEXR or libpng)";
        add += std::string(add.empty() ? "" : " ") + "--images none";
    }
    return "this canopy is timing-only (built with CANOPY_TIMING_ONLY): it cannot " + lacks + "; add " + add +
           ", or use a full build (scripts/build)";
}

}  // namespace canopy
