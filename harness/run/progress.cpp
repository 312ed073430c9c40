#include "run/progress.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <unistd.h>

namespace canopy {

namespace {

std::string clock_text(double seconds) {
    const long s = long(seconds + 0.5);
    return s >= 3600 ? fmt::format("{}:{:02}:{:02}", s / 3600, (s / 60) % 60, s % 60) : fmt::format("{}:{:02}", s / 60, s % 60);
}

}  // namespace

Progress::Progress(size_t total_cases)
    : total_(total_cases), terminal_(isatty(STDERR_FILENO) != 0), start_(std::chrono::steady_clock::now()) {}

void Progress::draw_bar(size_t done, const std::string& label) {
    constexpr int kWidth = 28;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const int filled = total_ ? int(kWidth * done / total_) : kWidth;
    const std::string eta = done ? clock_text(elapsed / double(done) * double(total_ - done)) : "?";
    std::string text = fmt::format("\r[{}{}] {}/{}  elapsed {}  ETA {}  {}", std::string(size_t(filled), '#'),
                                   std::string(size_t(kWidth - filled), '.'), done, total_, clock_text(elapsed), eta, label);
    if (text.size() > 120) text.resize(120);
    fmt::print(stderr, "{}\033[K", text);
    std::fflush(stderr);
}

void Progress::start_case(size_t index, const std::string& label) {
    if (terminal_) draw_bar(index, label);
    else fmt::print(stderr, "[{}/{}] {} ...\n", index + 1, total_, label);
}

void Progress::update_label(size_t index, const std::string& label) {
    if (terminal_) draw_bar(index, label);
}

void Progress::finish_case(size_t index, const std::string& label, double seconds, bool ok) {
    if (terminal_) {
        if (!ok) fmt::print(stderr, "\r\033[K[{}/{}] {} FAILED\n", index + 1, total_, label);
        draw_bar(index + 1, label);
    } else {
        fmt::print(stderr, "[{}/{}] {} {} in {:.1f} s\n", index + 1, total_, label, ok ? "done" : "FAILED", seconds);
    }
}

void Progress::done() {
    if (terminal_) fmt::print(stderr, "\r\033[K");
}

}  // namespace canopy
