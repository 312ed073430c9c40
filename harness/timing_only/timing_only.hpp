// A timing-only canopy (CMake option CANOPY_TIMING_ONLY) links neither the image-file libraries
// (OpenEXR, libpng) nor Embree.
// timing_only/*.cpp stand in for the functions that call them; main() refuses the options that
// would reach one first (timing_only_refusal), so a stand-in throwing is an internal error.
#pragma once

#include <optional>
#include <string>

namespace canopy {

// True in a timing-only build.
constexpr bool kTimingOnlyBuild =
#ifdef CANOPY_TIMING_ONLY
    true;
#else
    false;
#endif

// Thrown by a stand-in; names what the build lacks.
[[noreturn]] void throw_timing_only(const std::string& what);

// What a build cannot do for a command given these options (a timing-only one: references and
// image files), or nothing when it can. main() passes kTimingOnlyBuild.
std::optional<std::string> timing_only_refusal(bool timing_only_build, bool wants_reference, bool writes_images);

}  // namespace canopy
