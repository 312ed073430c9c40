// A write that fails says why, in the system's words, and leaves neither a temporary file nor a
// half-written result. Real failures only: a missing folder, and RLIMIT_FSIZE (a file-size limit
// holds for root too, unlike permissions) standing in for a full disk.
#include "core/image.hpp"
#include "report/atomic_file.hpp"
#include "report/image_files.hpp"
#include "support/temp_folder.hpp"

#include <doctest/doctest.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/resource.h>

using namespace canopy;
namespace fs = std::filesystem;

namespace {

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

size_t temporary_files(const fs::path& dir) {
    size_t count = 0;
    for (const auto& entry : fs::directory_iterator(dir)) count += is_temporary_file(entry.path()) ? 1 : 0;
    return count;
}

// Files larger than `bytes` cannot be written while it lives (EFBIG instead of SIGXFSZ).
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes) {
        getrlimit(RLIMIT_FSIZE, &saved_);
        previous_handler_ = std::signal(SIGXFSZ, SIG_IGN);
        rlimit limit = saved_;
        limit.rlim_cur = bytes;
        REQUIRE(setrlimit(RLIMIT_FSIZE, &limit) == 0);
    }
    ~FileSizeLimit() {
        setrlimit(RLIMIT_FSIZE, &saved_);
        std::signal(SIGXFSZ, previous_handler_);
    }

private:
    rlimit saved_{};
    void (*previous_handler_)(int) = nullptr;
};

}  // namespace

TEST_CASE("a written file replaces the old one whole, and no temporary file stays") {
    const test::TempFolder folder;
    const fs::path dir = folder.path() / "atomic";
    fs::create_directories(dir);
    write_text_atomically(dir / "results.json", "first");
    write_text_atomically(dir / "results.json", "second");
    CHECK(read_text(dir / "results.json") == "second");
    CHECK(temporary_files(dir) == 0);
    CHECK(is_temporary_file(temporary_path(dir / "results.json")));
    CHECK(is_temporary_file(temporary_path(dir / "images" / "a.error.png")));
    CHECK_FALSE(is_temporary_file(dir / "results.json"));
    CHECK_FALSE(is_temporary_file(dir / "tiny_96x64_shadow.pcf_kernel-3.exr"));
}

TEST_CASE("a write into a missing folder names the file and the system's reason") {
    const test::TempFolder folder;
    const fs::path dir = folder.path() / "missing";
    fs::create_directories(dir);
    const fs::path target = dir / "gone" / "results.json";
    try {
        write_text_atomically(target, "x");
        FAIL("no error");
    } catch (const WriteError& e) {
        CHECK(e.code() == ENOENT);
        CHECK(std::string(e.what()) == "cannot write " + target.string() + ": " + std::strerror(ENOENT));
    }
    // Images too: OpenImageIO, which canopy used before, reported "cannot write image PATH: " with no reason.
    Image image(4, 4);
    for (const std::string name : {"a.exr", "a.png"}) {
        try {
            if (name == "a.exr") write_exr(dir / "gone" / name, image);
            else write_png_srgb(dir / "gone" / name, image);
            FAIL("no error");
        } catch (const std::exception& e) {
            CHECK(std::string(e.what()).find(std::strerror(ENOENT)) != std::string::npos);
        }
    }
}

TEST_CASE("a file that does not fit fails with the system's reason and keeps the previous version") {
    const test::TempFolder folder;
    const fs::path dir = folder.path() / "full";
    fs::create_directories(dir);
    write_text_atomically(dir / "results.json", "the previous record");
    Image image(64, 64);
    for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = float(i % 97) / 97.0f;
    {
        const FileSizeLimit limit(1000);
        try {
            write_text_atomically(dir / "results.json", std::string(5000, 'x'));
            FAIL("no error");
        } catch (const WriteError& e) {
            CHECK(e.code() == EFBIG);
            CHECK(std::string(e.what()).find(std::strerror(EFBIG)) != std::string::npos);
        }
        try {
            write_exr(dir / "image.exr", image);
            FAIL("no error");
        } catch (const WriteError& e) {
            CHECK(std::string(e.what()) == "cannot write " + (dir / "image.exr").string() + ": " + std::strerror(EFBIG));
        }
    }
    CHECK(read_text(dir / "results.json") == "the previous record");
    CHECK_FALSE(fs::exists(dir / "image.exr"));
    CHECK(temporary_files(dir) == 0);
}
