#include "report/atomic_file.hpp"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <regex>
#include <unistd.h>

namespace canopy {

namespace {

// The test-only failure hook (see atomic_file.hpp): whether this write is one that must fail.
bool injected_failure() {
    struct Hook {
        long after = -1;  // writes that succeed first; -1: no hook
        bool persistent = false;
    };
    static const Hook hook = [] {
        Hook h;
        if (const char* value = std::getenv(kFailWriteAfterVariable); value && *value) {
            char* end = nullptr;
            h.after = std::strtol(value, &end, 10);
            h.persistent = end && *end == '+';
        }
        return h;
    }();
    static std::atomic<long> writes{0};
    if (hook.after < 0) return false;
    const long index = writes.fetch_add(1);  // 0-based number of this write
    return hook.persistent ? index >= hook.after : index == hook.after;
}

// Writes all of `bytes` to the open file `fd`; returns 0 or the errno of the failure.
int write_all(int fd, std::string_view bytes, bool fail) {
    if (fail) return ENOSPC;
    while (!bytes.empty()) {
        const ssize_t written = ::write(fd, bytes.data(), bytes.size());
        if (written < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        bytes.remove_prefix(size_t(written));
    }
    return 0;
}

// Writes `bytes` to `temp`, then renames it to `path`; `fail`: the test hook's failure.
void write_then_rename(const std::filesystem::path& temp, const std::filesystem::path& path, std::string_view bytes,
                       bool fail) {
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) {
        const int code = errno;
        throw WriteError(path, code, std::strerror(code));
    }
    // No fsync: this protects readers and killed processes from half-written files, not a power cut.
    int code = write_all(fd, bytes, fail);
    if (::close(fd) != 0 && code == 0) code = errno;  // some filesystems report a full disk only here
    if (code == 0 && std::rename(temp.c_str(), path.c_str()) != 0) code = errno;
    if (code != 0) {
        ::unlink(temp.c_str());
        throw WriteError(path, code, std::strerror(code));
    }
}

}  // namespace

WriteError::WriteError(const std::filesystem::path& path, int code, const std::string& reason)
    : std::runtime_error("cannot write " + path.string() + ": " + reason), code_(code) {}

std::filesystem::path temporary_path(const std::filesystem::path& path) {
    std::string name = ".";
    name += path.stem().string();
    name += ".tmp";
    name += std::to_string(getpid());
    name += path.extension().string();
    std::filesystem::path temp = path;
    temp.replace_filename(name);
    return temp;
}

bool is_temporary_file(const std::filesystem::path& file) {
    static const std::regex pattern(R"(\..*\.tmp[0-9]+(\.[A-Za-z0-9]+)?)");
    return std::regex_match(file.filename().string(), pattern);
}

void write_bytes_atomically(const std::filesystem::path& path, std::string_view bytes) {
    write_then_rename(temporary_path(path), path, bytes, injected_failure());
}

void write_bytes_through(const std::filesystem::path& temporary, const std::filesystem::path& path,
                         std::string_view bytes) {
    write_then_rename(temporary, path, bytes, false);
}

void write_text_atomically(const std::filesystem::path& path, const std::string& content) {
    write_bytes_atomically(path, content);
}

}  // namespace canopy
