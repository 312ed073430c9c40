// Progress of a multi-case run on stderr: a bar with ETA on a terminal, plain lines otherwise.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace canopy {

class Progress {
public:
    explicit Progress(size_t total_cases);
    void start_case(size_t index, const std::string& label);
    // Redraws the bar with a new label (terminal only), e.g. for progress within a case.
    void update_label(size_t index, const std::string& label);
    void finish_case(size_t index, const std::string& label, double seconds, bool ok);
    void done();

private:
    void draw_bar(size_t done, const std::string& label);
    size_t total_;
    bool terminal_;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace canopy
