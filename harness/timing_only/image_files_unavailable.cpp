// Stand-ins for report/image_files.cpp in a timing-only build (timing_only.hpp).
#include "report/image_files.hpp"
#include "timing_only/timing_only.hpp"


namespace canopy {

void write_exr(const std::filesystem::path& path, const Image&) { throw_timing_only("writing " + path.string()); }
void write_png_srgb(const std::filesystem::path& path, const Image&) { throw_timing_only("writing " + path.string()); }
void write_png_display(const std::filesystem::path& path, const Image&) {
    throw_timing_only("writing " + path.string());
}
Image read_image(const std::filesystem::path& path) { throw_timing_only("reading " + path.string()); }

}  // namespace canopy
