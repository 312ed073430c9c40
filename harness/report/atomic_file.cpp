#include "report/atomic_file.hpp"

#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace canopy {

void write_atomically(const std::filesystem::path& path, const std::function<void(const std::filesystem::path&)>& write) {
    std::filesystem::path temp = path;
    temp.replace_filename("." + path.stem().string() + ".tmp" + std::to_string(getpid()) + path.extension().string());
    try {
        write(temp);
        std::filesystem::rename(temp, path);
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(temp, ignored);
        throw;
    }
}

void write_text_atomically(const std::filesystem::path& path, const std::string& content) {
    write_atomically(path, [&](const std::filesystem::path& temp) {
        std::ofstream out(temp, std::ios::binary);
        out << content;
        out.close();
        if (!out) throw std::runtime_error("cannot write " + temp.string());
    });
}

}  // namespace canopy
