#include "run/recorded_path.hpp"

#include "run/environment.hpp"

#include <algorithm>

namespace canopy {

std::string recorded_path(const std::filesystem::path& path) {
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::path full = fs::weakly_canonical(fs::absolute(path), error);
    if (error) return path.generic_string();
    const fs::path root = fs::weakly_canonical(run_checkout(), error);
    if (!error) {
        const auto [root_end, full_at] = std::mismatch(root.begin(), root.end(), full.begin(), full.end());
        if (root_end == root.end()) return full.lexically_relative(root).generic_string();
    }
    return full.generic_string();
}

}  // namespace canopy
