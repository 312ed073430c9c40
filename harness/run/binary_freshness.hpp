// Whether the canopy binary is older than the sources it was built from: a binary linked before
// a source changed (an edit not rebuilt, a break check restored with cp) measures other code than
// the commit its results name. Checked by file times, so any later edit counts, even one that
// restores the same bytes: a warning too many rather than a number misattributed.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace canopy {

// A source file under `checkout` (harness/ and techniques/: C++ and GLSL, a family's tests/ left
// out, as canopy is not built from them) modified after `built`,
// relative to `checkout`: the newest one; nothing when none is, or when the folders are absent.
std::optional<std::filesystem::path> source_newer_than(const std::filesystem::path& checkout,
                                                       std::filesystem::file_time_type built);

// source_newer_than for this executable and the checkout it was built from, as a string ("" when
// the binary is as new as its sources, or either cannot be read).
std::string source_newer_than_this_binary();

}  // namespace canopy
