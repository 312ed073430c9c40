// Results are written atomically: to a temporary file in the same folder, then renamed, so a
// reader (or an interrupted run) never sees a half-written file.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace canopy {

void write_text_atomically(const std::filesystem::path& path, const std::string& content);

// Calls `write(temp_path)` to produce the file under a temporary name that keeps the
// extension (image libraries choose the format from it), then renames it into place.
void write_atomically(const std::filesystem::path& path, const std::function<void(const std::filesystem::path&)>& write);

}  // namespace canopy
