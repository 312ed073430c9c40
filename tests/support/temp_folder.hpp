// A fresh folder for a test that writes files (configs, scenes, outputs), removed with everything
// in it when the test ends, also when it fails.
#pragma once

#include <filesystem>
#include <string>

namespace canopy::test {

class TempFolder {
public:
    // A new, empty folder under the system's temporary directory, named "<prefix>-XXXXXX".
    explicit TempFolder(const std::string& prefix = "canopy-test");
    ~TempFolder();
    TempFolder(const TempFolder&) = delete;
    TempFolder& operator=(const TempFolder&) = delete;

    const std::filesystem::path& path() const { return path_; }
    // Writes `text` to `name` inside the folder (creating sub-folders) and returns its path.
    std::filesystem::path write(const std::string& name, const std::string& text) const;

private:
    std::filesystem::path path_;
};

}  // namespace canopy::test
