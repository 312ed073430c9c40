#include "run/kernel_scaling.hpp"

#include "config/scene_config.hpp"
#include "gpu/context.hpp"
#include "run/group_measurement.hpp"
#include "run/recorded_path.hpp"
#include "run/statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace canopy {

namespace {

struct SweepSpec {
    std::string technique, parameter;
    std::vector<long long> widths;
    std::vector<std::string> passes;  // summed; the lit pass for per-pixel kernels
    double expected;
    std::map<std::string, ParamValue> fixed;
};

std::vector<SweepSpec> sweeps() {
    const std::vector<long long> filters{3, 7, 11, 15, 21, 31};
    const std::vector<std::string> prefilter{"prefilter_x", "prefilter_y"};
    return {
        {"shadow.pcf", "kernel", {1, 3, 5, 7, 9, 11}, {"lit"}, 2.0, {}},
        {"shadow.pcss", "kernel", {1, 5, 9, 13, 17, 23}, {"lit"}, 2.0, {{"blocker_search", 5LL}}},
        {"shadow.ssss", "kernel", {5, 9, 13, 17, 23, 31}, {"blur_x", "blur_y"}, 1.0, {}},
        {"shadow.vsm", "filter", filters, prefilter, 1.0, {}},
        {"shadow.esm", "filter", filters, prefilter, 1.0, {}},
        {"shadow.gauss-cdf", "filter", filters, prefilter, 1.0, {}},
        {"shadow.power-cdf", "filter", filters, prefilter, 1.0, {}},
        {"shadow.evsm", "filter", filters, prefilter, 1.0, {}},
        {"shadow.msm", "filter", filters, prefilter, 1.0, {}},
    };
}

}  // namespace

PowerFit fit_power_law(const std::vector<double>& widths, const std::vector<double>& times) {
    PowerFit best;
    double best_sse = std::numeric_limits<double>::infinity();
    const size_t n = widths.size();
    double mean_t = 0;
    for (double t : times) mean_t += t / double(n);
    for (double p = 0.2; p <= 3.5 + 1e-9; p += 0.005) {
        // Linear least squares of t = a + b x with x = w^p.
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (size_t i = 0; i < n; ++i) {
            const double x = std::pow(widths[i], p);
            sx += x;
            sy += times[i];
            sxx += x * x;
            sxy += x * times[i];
        }
        const double det = double(n) * sxx - sx * sx;
        if (std::abs(det) < 1e-300) continue;
        double b = (double(n) * sxy - sx * sy) / det;
        double a = (sy - b * sx) / double(n);
        if (a < 0) {  // a fixed cost cannot be negative: fit through the origin instead
            a = 0;
            b = sxy / sxx;
        }
        if (b <= 0) continue;  // time must grow with the kernel
        double sse = 0;
        for (size_t i = 0; i < n; ++i) {
            const double r = times[i] - (a + b * std::pow(widths[i], p));
            sse += r * r;
        }
        if (sse < best_sse) {
            best_sse = sse;
            best = {a, b, p, 0};
        }
    }
    double sst = 0;
    for (double t : times) sst += (t - mean_t) * (t - mean_t);
    best.r_squared = sst > 0 ? 1.0 - best_sse / sst : 1.0;
    return best;
}

std::vector<ScalingSeries> run_kernel_scaling(const TechniqueRegistry& registry, const GpuContext& gpu,
                                              const ScalingOptions& options) {
    const Scene scene = load_scene(options.scene_file);
    const auto meshes = build_scene_meshes(scene);
    std::vector<ScalingSeries> all;
    for (const SweepSpec& sweep : sweeps()) {
        const Technique* technique = registry.find(sweep.technique);
        if (!technique) continue;
        ScalingSeries s{sweep.technique, sweep.parameter, sweep.passes, {}, {}, {}, {}, sweep.expected};
        // A technique's widths are measured together, round by round (run/group_measurement.hpp), so
        // a change of the machine's load falls on every width alike instead of bending the curve.
        std::vector<Case> cases;
        for (long long width : sweep.widths) {
            auto given = sweep.fixed;
            given[sweep.parameter] = width;
            Case c;
            c.technique = sweep.technique;
            c.resolution = {options.width, options.height};
            c.params = ParamSet::resolve(technique->params(), given, {}, {}, sweep.technique);
            c.id = fmt::format("{}_{}-{}", sweep.technique, sweep.parameter, width);
            cases.push_back(std::move(c));
        }
        GroupInput input;
        input.name = fmt::format("{} {}x{}", scene.name, options.width, options.height);
        input.scene = &scene;
        input.meshes = &meshes;
        for (const Case& c : cases) input.cases.push_back({&c, technique, 0});
        MeasurementSettings settings;
        settings.warmup_frames = options.warmup;
        settings.rounds = options.measured;
        GroupCallbacks callbacks;
        if (options.show_progress)
            callbacks.round_started = [&](size_t, size_t widths, int round, int rounds) {
                fmt::print(stderr, "scaling: {}, {} widths interleaved, round {}/{}\n", sweep.technique, widths, round,
                           rounds);
            };
        const std::optional<MeasuredGroup> measured = measure_group(gpu, input, settings, ChunkLimits{}, callbacks);
        if (!measured) break;  // interrupted
        for (size_t k = 0; k < cases.size(); ++k) {
            const CaseResult& result = measured->cases[k];
            if (!result.ok) throw GpuError(fmt::format("{}: {}", result.id, result.error));
            // Per round, the sum of the passes the kernel affects.
            std::vector<double> samples(result.gpu_frame.samples_ms.size(), 0.0);
            for (const TimingSeries& pass : result.passes)
                if (std::find(sweep.passes.begin(), sweep.passes.end(), pass.name) != sweep.passes.end())
                    for (size_t i = 0; i < samples.size() && i < pass.samples_ms.size(); ++i) samples[i] += pass.samples_ms[i];
            const SampleStats stats = summarize(samples);
            s.widths.push_back(double(sweep.widths[k]));
            s.median_ms.push_back(stats.median);
            s.mad_ms.push_back(stats.mad);
        }
        s.fit = fit_power_law(s.widths, s.median_ms);
        all.push_back(std::move(s));
    }
    return all;
}

std::string kernel_scaling_report(const std::vector<ScalingSeries>& series, const Environment& e,
                                  const ScalingOptions& options) {
    std::string out = "# Kernel-size scaling\n\n";
    out += fmt::format("Time of the passes a kernel affects against its width, fitted as t = a + b·width^p "
                       "(least squares over p in [0.2, 3.5], a ≥ 0 and b linear). Separable filters should give p ≈ 1, "
                       "K×K kernels (PCF, PCSS) p ≈ 2. Scene `{}` at {}x{}; per technique, every width renders {} "
                       "warm-up frames, then {} rounds in which each width renders one frame in turn (interleaved, "
                       "the median over the rounds is the point); canopy {} on {} ({}), nproc {}, LP_NUM_THREADS {}, commit {}.\n\n",
                       recorded_path(options.scene_file), options.width, options.height, options.warmup, options.measured,
                       e.canopy_version, e.device.name, e.device.driver_info, e.nproc, e.lp_num_threads, commit_text(e));
    out += "| technique | swept | passes timed | fitted p | expected | R² | a (ms) | widths: median ms |\n";
    out += "|---|---|---|---:|---:|---:|---:|---|\n";
    for (const auto& s : series) {
        std::string points, passes;
        for (size_t i = 0; i < s.widths.size(); ++i)
            points += fmt::format("{}{}: {:.2f}", i ? ", " : "", s.widths[i], s.median_ms[i]);
        for (const auto& p : s.passes) passes += (passes.empty() ? "" : " + ") + p;
        out += fmt::format("| {} | {} | {} | {:.2f} | {:.0f} | {:.3f} | {:.2f} | {} |\n", s.technique, s.parameter,
                           passes, s.fit.exponent, s.expected_exponent, s.fit.r_squared, s.fit.offset, points);
    }
    out += "\nThe lit pass of PCF and PCSS also shades every pixel: that fixed cost is the fit's offset a. PCSS's "
           "PCF taps are spread over a per-pixel penumbra, but their number is K² whatever the width.\n";
    return out;
}

}  // namespace canopy
