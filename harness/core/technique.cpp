#include "core/technique.hpp"

namespace canopy {

const char* to_string(DepthFormat format) { return format == DepthFormat::d16 ? "d16" : "d32f"; }

}  // namespace canopy
