// Results are written atomically: to a temporary file in the same folder, then renamed, so a
// reader (or an interrupted run) never sees a half-written file. A failed write says why, in the
// system's words ("No space left on device"), and leaves no temporary file behind.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace canopy {

// A file could not be written: "cannot write PATH: REASON". `code()` is the errno value.
class WriteError : public std::runtime_error {
public:
    WriteError(const std::filesystem::path& path, int code, const std::string& reason);
    int code() const { return code_; }

private:
    int code_;
};

// Throws WriteError when the temporary file cannot be created, written, closed or renamed.
void write_bytes_atomically(const std::filesystem::path& path, std::string_view bytes);
// The same through a temporary file the caller names, in `path`'s folder: for a writer that
// several threads of one process may run on one path (the reference cache), whose files are not a
// run's outputs and so not counted by the test hook below.
void write_bytes_through(const std::filesystem::path& temporary, const std::filesystem::path& path,
                         std::string_view bytes);
void write_text_atomically(const std::filesystem::path& path, const std::string& content);

// The temporary name a write uses until it is renamed into place: ".<stem>.tmp<pid><extension>"
// next to `path` (the extension is kept for tools that look at it).
std::filesystem::path temporary_path(const std::filesystem::path& path);
// Whether `file` is such a temporary file, e.g. one left by a killed process.
bool is_temporary_file(const std::filesystem::path& file);

// TEST-ONLY hook, for tests of full disks (CI runs as root without the right to mount a small
// filesystem, so permissions and quotas cannot make a write fail there):
//   CANOPY_TEST_FAIL_WRITE_AFTER=N   the (N+1)-th file write of the process fails with ENOSPC;
//   CANOPY_TEST_FAIL_WRITE_AFTER=N+  every write after the first N fails (a disk that stays full).
// Unset in normal use; nothing else reads it.
inline constexpr const char* kFailWriteAfterVariable = "CANOPY_TEST_FAIL_WRITE_AFTER";

}  // namespace canopy
