// Progress of a multi-case run on stderr: a bar on a terminal, plain lines otherwise. It says
// where each reference comes from (the cache, or ray-traced now) and when it is done, and an
// estimate of the time the run has left.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <optional>
#include <string>

namespace canopy {

// Seconds a run has left: the cases measured so far took `case_seconds` in all, the references
// obtained so far `reference_seconds` (a cached one takes almost nothing). Nullopt until a case
// has been measured.
std::optional<double> estimate_remaining_seconds(double case_seconds, size_t cases_measured, size_t cases_left,
                                                 double reference_seconds, size_t references_done,
                                                 size_t references_left);

// "1:05" or "1:02:05"
std::string clock_text(double seconds);

class Progress {
public:
    // `references` is how many references the cases still to run need. `terminal` defaults to
    // whether `out` is one. Not on a terminal, a line says where the run is at least every
    // `heartbeat_seconds` while a reference is traced or a group measured (a log or a batch job
    // shows it is alive).
    Progress(size_t total_cases, size_t references, std::FILE* out = stderr, std::optional<bool> terminal = {},
             double heartbeat_seconds = 30.0);

    void kept_case(size_t index, const std::string& label);  // finished by the run this one continues
    void reference_started(size_t index, const std::string& name, bool from_cache);
    void reference_progress(size_t index, const std::string& name, double fraction);
    void reference_finished(size_t index, const std::string& name, double seconds, bool from_cache);
    void start_case(size_t index, const std::string& label);
    // A group's cases are measured together, round by round (run/group_measurement.hpp).
    // `chunks` is how many chunks the group's cases take at least (run/group_measurement.hpp).
    void start_group(size_t first_index, const std::string& group, size_t cases, int rounds, size_t chunks = 1);
    void group_round(const std::string& group, size_t chunk, size_t cases, int round, int rounds);
    void finish_case(size_t index, const std::string& label, double seconds, bool ok);
    void done();  // "finished N cases in 0:12"

    std::optional<double> remaining_seconds() const;

private:
    void draw_bar(size_t done, const std::string& label);
    void line(const std::string& text);  // a line that stays
    bool heartbeat_due() const;
    double elapsed() const;  // seconds since the run began          // not a terminal, and no line for heartbeat_seconds
    std::string eta_text() const;

    size_t total_, references_left_;
    std::FILE* out_;
    bool terminal_;
    double heartbeat_seconds_;
    std::chrono::steady_clock::time_point start_, last_line_;
    size_t group_chunks_ = 1;
    size_t done_ = 0, kept_ = 0, measured_ = 0, references_done_ = 0;
    double case_seconds_ = 0, reference_seconds_ = 0;
};

}  // namespace canopy
