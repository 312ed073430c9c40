#include "run/progress.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <unistd.h>

namespace canopy {

std::string clock_text(double seconds) {
    const long s = long(seconds + 0.5);
    return s >= 3600 ? fmt::format("{}:{:02}:{:02}", s / 3600, (s / 60) % 60, s % 60) : fmt::format("{}:{:02}", s / 60, s % 60);
}

std::optional<double> estimate_remaining_seconds(double case_seconds, size_t cases_measured, size_t cases_left,
                                                 double reference_seconds, size_t references_done,
                                                 size_t references_left) {
    if (cases_measured == 0) return std::nullopt;
    double left = case_seconds / double(cases_measured) * double(cases_left);
    if (references_done > 0) left += reference_seconds / double(references_done) * double(references_left);
    return left;
}

Progress::Progress(size_t total_cases, size_t references, std::FILE* out, std::optional<bool> terminal,
                   double heartbeat_seconds)
    : total_(total_cases),
      references_left_(references),
      out_(out),
      terminal_(terminal.value_or(isatty(fileno(out)) != 0)),
      heartbeat_seconds_(heartbeat_seconds),
      start_(std::chrono::steady_clock::now()),
      last_line_(start_) {}

double Progress::elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

bool Progress::heartbeat_due() const {
    return !terminal_ &&
           std::chrono::duration<double>(std::chrono::steady_clock::now() - last_line_).count() >= heartbeat_seconds_;
}

std::optional<double> Progress::remaining_seconds() const {
    return estimate_remaining_seconds(case_seconds_, measured_, total_ - done_, reference_seconds_, references_done_,
                                      references_left_);
}

std::string Progress::eta_text() const {
    const auto left = remaining_seconds();
    return left ? clock_text(*left) : "?";
}

void Progress::draw_bar(size_t done, const std::string& label) {
    constexpr int kWidth = 28;
    const int filled = total_ ? int(kWidth * done / total_) : kWidth;
    std::string text = fmt::format("\r[{}{}] {}/{}  elapsed {}  ETA {}  {}", std::string(size_t(filled), '#'),
                                   std::string(size_t(kWidth - filled), '.'), done, total_, clock_text(elapsed()),
                                   eta_text(), label);
    if (text.size() > 120) text.resize(120);
    fmt::print(out_, "{}\033[K", text);
    std::fflush(out_);
}

void Progress::line(const std::string& text) {
    if (terminal_) fmt::print(out_, "\r\033[K{}\n", text);
    else fmt::print(out_, "{}\n", text);
    std::fflush(out_);
    last_line_ = std::chrono::steady_clock::now();
}

void Progress::kept_case(size_t index, const std::string& label) {
    ++done_;
    ++kept_;
    if (!terminal_) line(fmt::format("[{}/{}] {} kept from the earlier run", index + 1, total_, label));
}

void Progress::reference_started(size_t index, const std::string& name, bool from_cache) {
    const std::string text = from_cache ? fmt::format("reference {}: from the cache", name)
                                        : fmt::format("ray-tracing reference {} ...", name);
    if (terminal_) draw_bar(done_, text);
    else line(fmt::format("[{}/{}] {}", index + 1, total_, text));
}

void Progress::reference_progress(size_t index, const std::string& name, double fraction) {
    const std::string text = fmt::format("ray-tracing reference {} {:.0f}%", name, 100.0 * fraction);
    if (terminal_) draw_bar(done_, text);
    else if (heartbeat_due()) line(fmt::format("[{}/{}] {}, elapsed {}", index + 1, total_, text, clock_text(elapsed())));
}

void Progress::reference_finished(size_t index, const std::string& name, double seconds, bool from_cache) {
    ++references_done_;
    if (references_left_ > 0) --references_left_;
    reference_seconds_ += seconds;
    if (from_cache) return;  // reference_started said so
    line(fmt::format("[{}/{}] reference {} ray-traced in {:.1f} s", index + 1, total_, name, seconds));
}

void Progress::start_case(size_t index, const std::string& label) {
    if (terminal_) draw_bar(done_, label);
    else line(fmt::format("[{}/{}] {} ...", index + 1, total_, label));
}

void Progress::start_group(size_t first_index, const std::string& group, size_t cases, int rounds, size_t chunks) {
    group_chunks_ = std::max<size_t>(chunks, 1);
    std::string text = fmt::format("measuring {}: {} case{} interleaved, {} round{}", group, cases,
                                   cases == 1 ? "" : "s", rounds, rounds == 1 ? "" : "s");
    if (group_chunks_ > 1) text += fmt::format(", in {} chunks or more", group_chunks_);
    if (terminal_) draw_bar(done_, text);
    else line(fmt::format("[{}/{}] {} ...", first_index + 1, total_, text));
}

void Progress::group_round(const std::string& group, size_t chunk, size_t cases, int round, int rounds) {
    if (!terminal_) {
        // A line per round would bury the rest: one every heartbeat_seconds says the run is alive.
        if (heartbeat_due())
            line(fmt::format("[{}/{}] measuring {}: chunk {}/{}{} ({} cases), round {}/{}, elapsed {}, ETA {}", done_,
                             total_, group, chunk + 1, std::max(group_chunks_, chunk + 1),
                             chunk + 1 > group_chunks_ ? "+" : "", cases, round, rounds, clock_text(elapsed()),
                             eta_text()));
        return;
    }
    draw_bar(done_, chunk == 0 ? fmt::format("measuring {}: round {}/{}", group, round, rounds)
                               : fmt::format("measuring {} (chunk {}/{}, {} cases): round {}/{}", group, chunk + 1,
                                             std::max(group_chunks_, chunk + 1), cases, round, rounds));
}

void Progress::finish_case(size_t index, const std::string& label, double seconds, bool ok) {
    ++done_;
    ++measured_;
    case_seconds_ += seconds;
    if (terminal_) {
        if (!ok) line(fmt::format("[{}/{}] {} FAILED", index + 1, total_, label));
        draw_bar(done_, label);
    } else {
        line(fmt::format("[{}/{}] {} {} in {:.1f} s, ETA {}", index + 1, total_, label, ok ? "done" : "FAILED", seconds,
                         eta_text()));
    }
}

void Progress::done() {
    std::string text = fmt::format("finished {} of {} cases in {}", done_, total_, clock_text(elapsed()));
    if (kept_ > 0) text += fmt::format(" ({} kept from the earlier run)", kept_);
    line(text);
}

}  // namespace canopy
