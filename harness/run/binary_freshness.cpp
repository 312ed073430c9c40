#include "run/binary_freshness.hpp"

#include "run/environment.hpp"

#include <array>
#include <string_view>
#include <system_error>

namespace canopy {

namespace {

// C++ and GLSL: what the binary is compiled from. CMake files are left out: an edit there that
// changes the build rebuilds what it changes, and one that does not relinks nothing.
bool is_source(const std::filesystem::path& file) {
    static constexpr std::array<std::string_view, 8> kExtensions{".cpp", ".hpp", ".h", ".glsl",
                                                                 ".vert", ".frag", ".comp", ".geom"};
    const std::string extension = file.extension().string();
    for (std::string_view e : kExtensions)
        if (extension == e) return true;
    return false;
}

}  // namespace

std::optional<std::filesystem::path> source_newer_than(const std::filesystem::path& checkout,
                                                       std::filesystem::file_time_type built) {
    std::optional<std::filesystem::path> newest;
    std::filesystem::file_time_type newest_time = built;
    const auto consider = [&](const std::filesystem::path& file) {
        std::error_code error;
        const auto time = std::filesystem::last_write_time(file, error);
        if (!error && time > newest_time) {
            newest_time = time;
            newest = file.lexically_relative(checkout);
        }
    };
    for (const char* folder : {"harness", "techniques"}) {
        std::error_code error;
        for (auto it = std::filesystem::recursive_directory_iterator(checkout / folder, error);
             !error && it != std::filesystem::recursive_directory_iterator(); it.increment(error)) {
            // A family's tests are not in canopy: editing one relinks only its test binary.
            if (it->is_directory(error) && it->path().filename() == "tests") it.disable_recursion_pending();
            else if (it->is_regular_file(error) && is_source(it->path())) consider(it->path());
        }
    }
    return newest;
}

std::string source_newer_than_this_binary() {
    std::error_code error;
    const auto executable = std::filesystem::read_symlink("/proc/self/exe", error);
    if (error) return "";
    const auto built = std::filesystem::last_write_time(executable, error);
    if (error) return "";
    const auto newer = source_newer_than(source_checkout(), built);
    return newer ? newer->string() : "";
}

}  // namespace canopy
