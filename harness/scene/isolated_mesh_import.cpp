#include "scene/isolated_mesh_import.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <system_error>
#include <thread>
#include <type_traits>

#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace canopy {

namespace {

static_assert(std::is_trivially_copyable_v<Vertex> && sizeof(Vertex) == 6 * sizeof(float),
              "vertices travel between processes as raw bytes");

// What the child leaves in the shared file: this header, then either the vertices and indices
// (status mesh) or the error's message and hint (status error).
constexpr uint32_t kMagic = 0x6873656d;  // "mesh"
enum class ChildStatus : uint32_t { mesh = 1, error = 2 };
struct ChildHeader {
    uint32_t magic = kMagic;
    ChildStatus status = ChildStatus::error;
    uint64_t vertex_count = 0, index_count = 0;  // status mesh
    uint64_t message_bytes = 0, hint_bytes = 0;  // status error
};
// The child's exit code when it could not even write its answer.
constexpr int kChildWriteFailed = 3;

class FileDescriptor {
public:
    explicit FileDescriptor(int fd) : fd_(fd) {}
    ~FileDescriptor() {
        if (fd_ >= 0) close(fd_);
    }
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    int get() const { return fd_; }

private:
    int fd_;
};

bool write_all(int fd, const void* data, size_t size) {
    const char* bytes = static_cast<const char*>(data);
    while (size > 0) {
        const ssize_t written = write(fd, bytes, size);
        if (written < 0 && errno == EINTR) continue;
        if (written <= 0) return false;
        bytes += written;
        size -= size_t(written);
    }
    return true;
}

bool read_all_at(int fd, void* data, size_t size, off_t offset) {
    char* bytes = static_cast<char*>(data);
    while (size > 0) {
        const ssize_t got = pread(fd, bytes, size, offset);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) return false;
        bytes += got;
        size -= size_t(got);
        offset += got;
    }
    return true;
}

// Some files make assimp loop forever; a child that takes longer than this is killed.
constexpr const char* kTimeLimitVariable = "CANOPY_MESH_IMPORT_TIMEOUT";
constexpr double kDefaultTimeLimitSeconds = 300.0;

double import_time_limit_seconds() {
    if (const char* text = std::getenv(kTimeLimitVariable)) {
        char* end = nullptr;
        const double seconds = std::strtod(text, &end);
        if (end != text && *end == '\0' && seconds > 0.0 && seconds <= 1e6) return seconds;
    }
    return kDefaultTimeLimitSeconds;
}

// Waits for `child` to end, at most `seconds`; false when it is still running. Polls with a
// growing interval (0.1 ms to 20 ms): a mesh takes milliseconds to seconds, and waitpid has
// no timeout.
bool wait_for(pid_t child, int& status, double seconds) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    auto interval = std::chrono::microseconds(100);
    for (;;) {
        const pid_t ended = waitpid(child, &status, WNOHANG);
        if (ended == child) return true;
        if (ended < 0 && errno != EINTR) {
            const int error = errno;
            kill(child, SIGKILL);
            throw std::system_error(error, std::generic_category(), "mesh import: waitpid");
        }
        if (std::chrono::steady_clock::now() >= deadline) return false;
        std::this_thread::sleep_for(interval);
        interval = std::min(interval * 2, std::chrono::microseconds(20000));
    }
}

// Runs in the child: import, write the answer, and leave without running the parent's
// destructors or flushing its buffers (_exit).
[[noreturn]] void import_in_child(int fd, const std::filesystem::path& file) {
    const rlimit no_core{0, 0};
    setrlimit(RLIMIT_CORE, &no_core);  // a crash here is expected and reported; no core file
    if (const char* hook = std::getenv("CANOPY_TEST_MESH_IMPORT_SIGNAL")) {
        const int signal_number = std::atoi(hook);
        std::signal(signal_number, SIG_DFL);
        std::raise(signal_number);
    }

    ChildHeader header;
    TriangleMesh mesh;
    std::string message, hint;
    try {
        mesh = import_mesh_file(file);
        header.status = ChildStatus::mesh;
    } catch (const MeshFileError& error) {
        message = error.what();
        hint = error.hint();
    } catch (const std::exception& error) {
        message = fmt::format("cannot read mesh file '{}': {}", file.string(), error.what());
        hint = "check that the file is a complete model in a format assimp reads";
    }
    bool written = false;
    if (header.status == ChildStatus::mesh) {
        header.vertex_count = mesh.vertices.size();
        header.index_count = mesh.indices.size();
        written = write_all(fd, &header, sizeof(header)) &&
                  write_all(fd, mesh.vertices.data(), mesh.vertices.size() * sizeof(Vertex)) &&
                  write_all(fd, mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t));
    } else {
        header.message_bytes = message.size();
        header.hint_bytes = hint.size();
        written = write_all(fd, &header, sizeof(header)) && write_all(fd, message.data(), message.size()) &&
                  write_all(fd, hint.data(), hint.size());
    }
    _exit(written ? 0 : kChildWriteFailed);
}

// Reads the child's answer; anything inconsistent is an internal error, not the user's.
TriangleMesh read_answer(int fd, const std::filesystem::path& file) {
    struct stat info {};
    if (fstat(fd, &info) != 0) throw std::system_error(errno, std::generic_category(), "mesh import: fstat");
    const uint64_t size = uint64_t(info.st_size);
    ChildHeader header;
    const auto broken = [&](const char* what) {
        return std::runtime_error(fmt::format("mesh import of '{}': the child process's answer is {}", file.string(), what));
    };
    if (size < sizeof(header) || !read_all_at(fd, &header, sizeof(header), 0) || header.magic != kMagic)
        throw broken("missing");
    const uint64_t payload = size - sizeof(header);
    if (header.status == ChildStatus::error) {
        if (header.message_bytes > payload || header.hint_bytes != payload - header.message_bytes)
            throw broken("truncated");
        std::string message(header.message_bytes, '\0'), hint(header.hint_bytes, '\0');
        if (!read_all_at(fd, message.data(), message.size(), off_t(sizeof(header))) ||
            !read_all_at(fd, hint.data(), hint.size(), off_t(sizeof(header) + message.size())))
            throw broken("unreadable");
        throw MeshFileError(message, hint);
    }
    if (header.status != ChildStatus::mesh) throw broken("of an unknown kind");
    const uint64_t vertex_bytes = header.vertex_count * sizeof(Vertex);
    if (header.vertex_count > payload / sizeof(Vertex) || header.index_count > payload / sizeof(uint32_t) ||
        vertex_bytes + header.index_count * sizeof(uint32_t) != payload)
        throw broken("truncated");
    TriangleMesh mesh;
    mesh.vertices.resize(header.vertex_count);
    mesh.indices.resize(header.index_count);
    if (!read_all_at(fd, mesh.vertices.data(), vertex_bytes, off_t(sizeof(header))) ||
        !read_all_at(fd, mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t), off_t(sizeof(header) + vertex_bytes)))
        throw broken("unreadable");
    if (const auto defect = mesh_defect(mesh)) throw broken(defect->c_str());
    return mesh;
}

}  // namespace

TriangleMesh import_mesh_file_isolated(const std::filesystem::path& file) {
    const FileDescriptor shared(memfd_create("canopy-mesh-import", MFD_CLOEXEC));
    if (shared.get() < 0) throw std::system_error(errno, std::generic_category(), "mesh import: memfd_create");
    const pid_t child = fork();
    if (child < 0) throw std::system_error(errno, std::generic_category(), "mesh import: fork");
    if (child == 0) import_in_child(shared.get(), file);

    int status = 0;
    const double limit = import_time_limit_seconds();
    if (!wait_for(child, status, limit)) {
        kill(child, SIGKILL);
        while (waitpid(child, &status, 0) < 0 && errno == EINTR) {}
        throw MeshFileError(fmt::format("assimp did not finish reading '{}' within {:g} s (it may loop forever on "
                                        "this file)",
                                        file.string(), limit),
                            fmt::format("repair or re-export the model; for a model that takes longer to read, set "
                                        "{} to more seconds",
                                        kTimeLimitVariable));
    }
    const std::string hint = "assimp cannot read this file (a bug in assimp, likely triggered by a malformed file); "
                             "repair or re-export the model, or convert it to another format";
    if (WIFSIGNALED(status)) {
        const int signal_number = WTERMSIG(status);
        const char* name = strsignal(signal_number);
        throw MeshFileError(fmt::format("assimp crashed while reading '{}' (signal {}{}{})", file.string(), signal_number,
                                        name ? ", " : "", name ? name : ""),
                            hint);
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) == kChildWriteFailed)
        throw std::runtime_error(fmt::format("mesh import of '{}': the child process could not pass the mesh back "
                                             "(out of memory?)", file.string()));
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw MeshFileError(fmt::format("assimp crashed while reading '{}' (the reading process exited with status {})",
                                        file.string(), WIFEXITED(status) ? WEXITSTATUS(status) : -1),
                            hint);
    return read_answer(shared.get(), file);
}

}  // namespace canopy
