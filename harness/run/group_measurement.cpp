#include "run/environment.hpp"
#include "run/group_measurement.hpp"

#include "metrics/comparable_pair.hpp"
#include "render/frame_renderer.hpp"
#include "run/interrupt.hpp"
#include "run/round_order.hpp"
#include "run/test_ballast.hpp"

#include <fmt/chrono.h>
#include <fmt/format.h>

#include <chrono>
#include <ctime>
#include <memory>
#include <optional>

namespace canopy {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_between(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

double process_cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}


TimingSeries series(std::string name, std::vector<double> samples) {
    TimingSeries t{std::move(name), std::move(samples), {}};
    t.stats = summarize(t.samples_ms);
    return t;
}

// Per-series accumulation: element-wise sums of vectors that may grow.
void add_into(std::vector<double>& sum, const std::vector<double>& values) {
    if (sum.size() < values.size()) sum.resize(values.size(), 0.0);
    for (size_t i = 0; i < values.size(); ++i) sum[i] += values[i];
}

// One case while its group is measured: its renderer and the samples taken so far.
struct LiveCase {
    size_t index = 0;  // in the group
    CaseResult result;
    std::unique_ptr<FrameRenderer> renderer;
    std::unique_ptr<Ballast> ballast;
    Camera camera;                    // the scene's
    const CameraPath* path = nullptr;  // frames follow it when set
    uint32_t next_frame = 0;          // FrameState::frame_index of the next frame (warm-up included)
    std::function<void(size_t, const FrameState&)> frame_rendered;  // GroupCallbacks::frame_rendered
    std::vector<std::string> pass_names, cpu_pass_names;
    std::vector<std::vector<double>> pass_samples, cpu_pass_samples;
    std::vector<double> gpu, wall, cpu, record_cpu, start;
    std::vector<std::vector<double>> path_gpu;                // [path frame][round]
    std::vector<std::vector<std::vector<double>>> path_passes;  // [path frame][pass][round]
    std::vector<double> ratios;  // per round: GPU time / the baseline's it is paired with
    bool failed = false;

    void fail(const std::string& why) {
        failed = true;
        result.ok = false;
        result.error = why;
    }
    uint64_t bytes() const {
        if (!renderer) return 0;
        const MemoryUse m = renderer->memory();
        return m.technique_bytes + m.target_bytes + m.scene_bytes;
    }
    int path_frames() const { return path ? path->frames : 0; }

    // One frame at traversal frame `path_frame` of the path (the scene's camera without one), with
    // the test ballast after it when there is one.
    // The next frame of the run at `at`.
    FrameTiming render(const Camera& at, bool count_primitives = false) {
        const FrameState state{next_frame++, at};
        if (frame_rendered) frame_rendered(index, state);
        return count_primitives ? renderer->render_counting_primitives(state) : renderer->render(state);
    }
    FrameTiming frame(int path_frame, bool count_primitives = false) {
        FrameTiming t = render(path ? path->at(camera, path_frame) : camera, count_primitives);
        if (ballast) {
            const auto before = Clock::now();
            const double ballast_ms = ballast->run_ms();
            t.wall_ms += 1e3 * seconds_between(before, Clock::now());
            t.gpu_ms += ballast_ms;
            t.pass_gpu_ms.push_back(ballast_ms);
        }
        return t;
    }

    // One sample: `frames` frames (with a path: one traversal), each series the mean over them.
    struct Sample {
        std::vector<double> passes, cpu_passes;
        double gpu = 0, wall = 0, cpu = 0, record_cpu = 0, start = 0;
        std::vector<double> path_gpu;                // per path frame
        std::vector<std::vector<double>> path_passes;  // per path frame, per pass
        int count = 0;  // samples summed into this one

        void add(const Sample& s) {
            add_into(passes, s.passes);
            add_into(cpu_passes, s.cpu_passes);
            add_into(path_gpu, s.path_gpu);
            if (path_passes.size() < s.path_passes.size()) path_passes.resize(s.path_passes.size());
            for (size_t f = 0; f < s.path_passes.size(); ++f) add_into(path_passes[f], s.path_passes[f]);
            gpu += s.gpu;
            wall += s.wall;
            cpu += s.cpu;
            record_cpu += s.record_cpu;
            if (count == 0) start = s.start;
            count += s.count;
        }
    };
    Sample sample(int frames, double started_s) {
        if (path) frames = path->frames;
        Sample s;
        s.passes.assign(pass_names.size(), 0.0);
        s.cpu_passes.assign(cpu_pass_names.size(), 0.0);
        s.start = started_s;
        s.count = 1;
        const double cpu_before = process_cpu_ms();
        for (int f = 0; f < frames; ++f) {
            const FrameTiming t = frame(f);
            for (size_t p = 0; p < s.passes.size() && p < t.pass_gpu_ms.size(); ++p) s.passes[p] += t.pass_gpu_ms[p];
            for (size_t p = 0; p < s.cpu_passes.size() && p < t.pass_cpu_ms.size(); ++p) s.cpu_passes[p] += t.pass_cpu_ms[p];
            s.gpu += t.gpu_ms;
            s.wall += t.wall_ms;
            s.record_cpu += t.record_cpu_ms;
            if (path) {
                s.path_gpu.push_back(t.gpu_ms);
                s.path_passes.emplace_back(t.pass_gpu_ms.begin(),
                                           t.pass_gpu_ms.begin() + long(std::min(t.pass_gpu_ms.size(), pass_names.size())));
                s.path_passes.back().resize(pass_names.size(), 0.0);
            }
        }
        const double n = double(frames);
        for (double& p : s.passes) p /= n;
        for (double& p : s.cpu_passes) p /= n;
        s.gpu /= n;
        s.wall /= n;
        s.record_cpu /= n;
        s.cpu = (process_cpu_ms() - cpu_before) / n;
        return s;
    }
    // Records a round's sample (for the baseline under adjacent pairing: the mean of its samples
    // in the round).
    void record(const Sample& sum) {
        const double n = double(std::max(sum.count, 1));
        const auto mean_of = [n](const std::vector<double>& v, size_t i) { return i < v.size() ? v[i] / n : 0.0; };
        for (size_t p = 0; p < pass_samples.size(); ++p) pass_samples[p].push_back(mean_of(sum.passes, p));
        for (size_t p = 0; p < cpu_pass_samples.size(); ++p) cpu_pass_samples[p].push_back(mean_of(sum.cpu_passes, p));
        for (int f = 0; f < path_frames(); ++f) {
            path_gpu[size_t(f)].push_back(mean_of(sum.path_gpu, size_t(f)));
            static const std::vector<double> none;
            const std::vector<double>& frame_passes = size_t(f) < sum.path_passes.size() ? sum.path_passes[size_t(f)] : none;
            for (size_t p = 0; p < pass_names.size(); ++p) path_passes[size_t(f)][p].push_back(mean_of(frame_passes, p));
        }
        gpu.push_back(sum.gpu / n);
        wall.push_back(sum.wall / n);
        cpu.push_back(sum.cpu / n);
        record_cpu.push_back(sum.record_cpu / n);
        start.push_back(sum.start);
    }

    // Forgets the samples taken so far (the baseline's, between chunks: its record keeps the first
    // chunk's, each later chunk pairs with its own).
    void clear_samples() {
        for (auto& p : pass_samples) p.clear();
        for (auto& p : cpu_pass_samples) p.clear();
        for (auto& f : path_gpu) f.clear();
        for (auto& f : path_passes)
            for (auto& p : f) p.clear();
        gpu.clear();
        wall.clear();
        cpu.clear();
        record_cpu.clear();
        start.clear();
        ratios.clear();
    }

    void finish_timings(size_t chunk) {
        result.chunk = chunk;
        for (size_t p = 0; p < pass_names.size(); ++p) result.passes.push_back(series(pass_names[p], pass_samples[p]));
        for (size_t p = 0; p < cpu_pass_names.size(); ++p)
            result.cpu_passes.push_back(series(cpu_pass_names[p], cpu_pass_samples[p]));
        result.gpu_frame = series("gpu_frame", gpu);
        result.wall = series("wall", wall);
        result.cpu = series("cpu", cpu);
        result.record_cpu = series("record_cpu", record_cpu);
        result.sample_start_s = start;
        result.timing_check = check_pass_timing(pass_samples, wall);
        for (int f = 0; f < path_frames(); ++f) {
            CaseResult::PathFrame frame;
            frame.gpu_frame = series("gpu_frame", path_gpu[size_t(f)]);
            for (size_t p = 0; p < pass_names.size(); ++p)
                frame.passes.push_back(series(pass_names[p], path_passes[size_t(f)][p]));
            result.path_frames.push_back(std::move(frame));
        }
    }
};

// Builds a case's renderer (and ballast); a GpuError fails the case alone.
void build(LiveCase& live, const GpuContext& gpu, const GroupInput& group, const MeasurementSettings& settings) {
    const GroupCase& gc = group.cases[live.index];
    try {
        live.renderer = std::make_unique<FrameRenderer>(gpu, *group.scene, *group.meshes, uint32_t(gc.c->resolution.width),
                                                        uint32_t(gc.c->resolution.height), gc.technique->graph(gc.c->params));
        live.pass_names = live.renderer->pass_names();
        if (gc.ballast_iterations > 0) {
            live.ballast = std::make_unique<Ballast>(gpu, uint32_t(gc.c->resolution.width),
                                                     uint32_t(gc.c->resolution.height), gc.ballast_iterations);
            live.pass_names.push_back("test_ballast");
        }
        live.pass_samples.assign(live.pass_names.size(), {});
        live.cpu_pass_names = live.renderer->cpu_pass_names();
        live.cpu_pass_samples.assign(live.cpu_pass_names.size(), {});
        live.camera = group.scene->camera;
        live.path = settings.camera_path ? &*settings.camera_path : nullptr;
        live.path_gpu.assign(size_t(live.path_frames()), {});
        live.path_passes.assign(size_t(live.path_frames()), std::vector<std::vector<double>>(live.pass_names.size()));
        const FrameTiming& load = live.renderer->load_timing();
        const std::vector<std::string>& load_names = live.renderer->load_pass_names();
        live.result.load = {};
        for (size_t i = 0; i < load_names.size() && i < load.pass_gpu_ms.size(); ++i)
            live.result.load.pass_gpu_ms.emplace_back(load_names[i], load.pass_gpu_ms[i]);
        live.result.load.gpu_ms = load.gpu_ms;
        live.result.load.wall_ms = load.wall_ms;
        live.result.load.uploaded_bytes = load.uploaded_bytes;
        live.result.memory = live.renderer->memory();
        live.result.triangles = live.renderer->triangle_count();
        live.result.shadow_sampler = live.renderer->shadow_sampler();
    } catch (const GpuError& e) {
        live.renderer.reset();
        live.ballast.reset();
        live.fail(e.what());
    }
}

// Warm-up and rounds of one chunk. False when interrupted.
bool measure_chunk(std::vector<LiveCase*>& members, const MeasurementSettings& settings, size_t chunk_index,
                   MeasurementChunk& chunk, const GroupCallbacks& callbacks, bool with_baseline) {
    const auto begin = Clock::now();
    chunk.started_at = utc_now();
    if (with_baseline) members.front()->clear_samples();
    for (LiveCase* m : members) {
        chunk.cases.push_back(m->result.id);
        for (int i = 0; i < settings.warmup_frames && !m->failed; ++i) {
            if (interrupt_requested()) return false;
            try {
                // The first warm-up frame counts the triangles (untimed, so the count costs nothing)
                // and keeps the CPU passes' counts.
                const FrameTiming t = m->frame(i, i == 0);
                if (t.primitives) m->result.primitives = t.primitives;
                if (i == 0) m->result.counters = t.counters;
            } catch (const GpuError& e) {
                m->fail(e.what());
            }
        }
    }
    // One sample of `m` (a failure ends the case alone); nullopt when it failed.
    auto take = [&](LiveCase& m) -> std::optional<LiveCase::Sample> {
        if (m.failed) return std::nullopt;
        try {
            return m.sample(settings.frames_per_sample, seconds_between(begin, Clock::now()));
        } catch (const GpuError& e) {
            m.fail(e.what());
            return std::nullopt;
        }
    };
    const bool adjacent = settings.pairing == BaselinePairing::adjacent && with_baseline && members.size() > 1;
    for (int round = 0; round < settings.rounds; ++round) {
        if (callbacks.round_started) callbacks.round_started(chunk_index, members.size(), round + 1, settings.rounds);
        std::vector<size_t> sequence;  // positions in `members`, in the order they ran
        if (adjacent) {
            // B X B Y B Z B: each case between two baseline samples, divided by their mean.
            LiveCase& baseline = *members.front();
            LiveCase::Sample baseline_sum;
            if (interrupt_requested()) return false;
            std::optional<LiveCase::Sample> before = take(baseline);
            sequence.push_back(0);
            if (before) baseline_sum.add(*before);
            for (size_t k : round_order(members.size() - 1, size_t(round))) {
                LiveCase& m = *members[k + 1];
                if (m.failed) continue;
                if (interrupt_requested()) return false;
                const std::optional<LiveCase::Sample> sample = take(m);
                const std::optional<LiveCase::Sample> after = take(baseline);
                sequence.insert(sequence.end(), {k + 1, 0});
                if (after) baseline_sum.add(*after);
                if (sample) {
                    m.record(*sample);
                    if (before && after) m.ratios.push_back(sample->gpu / (0.5 * (before->gpu + after->gpu)));
                }
                before = after;
            }
            if (!baseline.failed) {
                baseline.record(baseline_sum);
                baseline.ratios.push_back(1.0);
            }
        } else {
            for (size_t k : round_order(members.size(), size_t(round))) {
                if (interrupt_requested()) return false;
                if (const std::optional<LiveCase::Sample> sample = take(*members[k])) members[k]->record(*sample);
                sequence.push_back(k);
            }
            // Each case divided by the baseline's sample of the same round.
            const LiveCase& baseline = *members.front();
            if (with_baseline && !baseline.failed && baseline.gpu.size() == size_t(round) + 1)
                for (LiveCase* m : members)
                    if (!m->failed && m->gpu.size() == size_t(round) + 1) m->ratios.push_back(m->gpu.back() / baseline.gpu.back());
        }
        chunk.orders.push_back(std::move(sequence));
    }
    if (with_baseline) chunk.baseline_gpu_ms = members.front()->gpu;
    chunk.seconds = seconds_between(begin, Clock::now());
    return true;
}

// Its timings, its ratio, its last image; then the callback.
void finish(LiveCase& live, size_t chunk_index, const MeasurementChunk& chunk, const GroupCallbacks& callbacks) {
    live.finish_timings(chunk_index);
    if (!chunk.baseline_gpu_ms.empty() && !live.failed && !live.ratios.empty()) {
        live.result.ratio.per_round = live.ratios;
        live.result.ratio.estimate = median_with_ci(live.ratios, bootstrap_seed(live.result.id));
    }
    Image image, visibility;
    std::vector<Image> path_images;
    if (live.renderer && !live.failed) {
        try {
            // Popping: one more traversal, untimed, in order (a technique keeping state across
            // frames sees the path as it was measured), every frame read back.
            if (live.path && live.path->popping && callbacks.path_rendered)
                for (int k = 0; k < live.path->frames; ++k) {
                    live.render(live.path->at(live.camera, k));
                    path_images.push_back(live.renderer->read_color());
                }
            // The reference is ray-traced from the scene's camera: after a path, one more frame
            // there (untimed), so the error measures the technique and not the camera's move.
            if (live.path) live.render(live.camera);
            FrameRenderer::ColorAndVisibility frame = live.renderer->read_color_and_pixel_visibility();
            image = std::move(frame.color);
            visibility = std::move(frame.visibility);
            live.result.nonfinite_pixels = count_nonfinite_pixels(image);
            if (live.result.nonfinite_pixels > 0)
                live.fail(fmt::format("{} pixels are NaN or Inf", live.result.nonfinite_pixels));
        } catch (const GpuError& e) {
            live.fail(e.what());
        }
    }
    if (callbacks.case_measured) callbacks.case_measured(live.index, live.result, std::move(image), std::move(visibility));
    if (!path_images.empty() && !live.failed) callbacks.path_rendered(live.index, live.result, std::move(path_images));
}

}  // namespace

RatioRecord paired_ratio(const std::vector<double>& series, const std::vector<double>& baseline, const std::string& label) {
    RatioRecord r;
    const size_t n = std::min(series.size(), baseline.size());
    for (size_t i = 0; i < n; ++i)
        if (series[i] > 0 && baseline[i] > 0) r.per_round.push_back(series[i] / baseline[i]);
    r.estimate = median_with_ci(r.per_round, bootstrap_seed(label));
    return r;
}

std::optional<MeasuredGroup> measure_group(const GpuContext& gpu, const GroupInput& group,
                                           const MeasurementSettings& settings, const ChunkLimits& limits,
                                           const GroupCallbacks& callbacks) {
    MeasuredGroup measured;
    measured.record.name = group.name;
    std::vector<LiveCase> live(group.cases.size());
    for (size_t i = 0; i < group.cases.size(); ++i) {
        const Case& c = *group.cases[i].c;
        live[i].index = i;
        live[i].frame_rendered = callbacks.frame_rendered;
        live[i].result.id = c.id;
        live[i].result.group_baseline = i == 0;
        live[i].result.scene = group.scene->name;
        live[i].result.scene_variant = group.scene->variant;
        live[i].result.technique = c.technique;
        live[i].result.resolution = c.resolution;
        live[i].result.params = c.params.values();
        live[i].result.params_summary = c.params.summary();
        measured.record.cases.push_back(c.id);
    }
    measured.record.scene = group.scene->name;
    if (!group.cases.empty()) measured.record.resolution = group.cases.front().c->resolution;
    measured.record.chunks = group.chunks_done;
    auto recorded_before = [&](size_t i) { return i < group.recorded.size() && group.recorded[i]; };

    // Finished cases not yet passed to chunk_finished, group indices.
    std::vector<size_t> unreported;
    auto report_finished = [&] {
        if (!callbacks.chunk_finished || unreported.empty()) return;
        std::vector<std::pair<size_t, const CaseResult*>> finished;
        for (size_t i : unreported) finished.emplace_back(i, &live[i].result);
        callbacks.chunk_finished(measured.record, finished);
        unreported.clear();
    };
    auto finish_case = [&](LiveCase& c, size_t chunk_index, const MeasurementChunk& chunk) {
        finish(c, chunk_index, chunk, callbacks);
        unreported.push_back(c.index);
    };

    // The baseline first; it stays built through every chunk.
    build(live[0], gpu, group, settings);
    const bool baseline_ok = !live[0].failed;
    bool baseline_finished = !baseline_ok || recorded_before(0);
    if (!baseline_ok && callbacks.case_measured) finish_case(live[0], measured.record.chunks.size(), MeasurementChunk{});
    size_t next = 1;
    do {
        std::vector<LiveCase*> members;
        uint64_t bytes = 0;
        if (baseline_ok) {
            members.push_back(&live[0]);
            bytes = live[0].bytes();
        }
        while (next < live.size() && members.size() < std::max<size_t>(limits.max_cases, 2)) {
            if (interrupt_requested()) return std::nullopt;
            LiveCase& candidate = live[next++];
            if (recorded_before(candidate.index)) continue;
            build(candidate, gpu, group, settings);
            if (candidate.failed) {
                finish_case(candidate, measured.record.chunks.size(), MeasurementChunk{});
                continue;
            }
            members.push_back(&candidate);
            bytes += candidate.bytes();
            if (bytes > limits.max_bytes) break;
        }
        // Every remaining case failed to build, or was recorded before: nothing left to measure.
        if (members.empty() || (members.size() == 1 && baseline_ok && baseline_finished)) break;
        const size_t chunk_index = measured.record.chunks.size();
        MeasurementChunk chunk;
        if (!measure_chunk(members, settings, chunk_index, chunk, callbacks, baseline_ok)) return std::nullopt;
        for (LiveCase* m : members) {
            const bool is_baseline = baseline_ok && m == &live[0];
            if (is_baseline && baseline_finished) continue;
            finish_case(*m, chunk_index, chunk);
            if (is_baseline) {
                baseline_finished = true;
            } else {
                m->renderer.reset();  // its memory goes back before the next chunk's renderers are built
                m->ballast.reset();
            }
        }
        measured.record.chunks.push_back(std::move(chunk));
        report_finished();
    } while (next < live.size());
    report_finished();  // cases that failed to build after the last chunk

    for (LiveCase& l : live) measured.cases.push_back(std::move(l.result));
    return measured;
}

}  // namespace canopy
