#include "report/csv_report.hpp"

#include "metrics/metric_registry.hpp"
#include "report/atomic_file.hpp"

#include <fmt/format.h>

#include <set>
#include <span>

namespace canopy {

namespace {

std::string quoted(const std::string& s) {
    std::string out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

// ",value" in full precision, or ",n/a" where the technique does not declare the column meaningful
// (ErrorColumns).
std::string value_or_na(double value, bool meaningful) { return meaningful ? fmt::format(",{}", value) : ",n/a"; }

}  // namespace

std::string csv_report(const RunRecord& run) {
    // Pass names differ between techniques: one column pair per pass seen in this run.
    std::vector<std::string> pass_names;
    std::set<std::string> seen;
    for (const auto& c : run.cases)
        for (const auto& p : c.passes)
            if (seen.insert(p.name).second) pass_names.push_back(p.name);

    std::string out = "id,scene,technique,params,width,height,ok,gpu_ms_median,gpu_ms_min,gpu_ms_mean,gpu_ms_mad,gpu_cv,"
                      "wall_ms_median,wall_ms_mad,wall_cv,cpu_ms_median,ratio,ratio_ci95_low,ratio_ci95_high,rounds,frames_per_sample";
    for (const auto& name : pass_names) out += fmt::format(",{0}_gpu_ms_median,{0}_gpu_ms_mad", name);
    out += ",technique_memory_bytes,target_memory_bytes,scene_memory_bytes,triangles,shadow_sampler,nonfinite_pixels";
    const std::span<const MetricInfo> metrics = registered_metrics();
    for (const MetricInfo& metric : metrics) out += fmt::format(",{}", metric.name);
    out += ",device,commit\n";
    for (const auto& c : run.cases) {
        out += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}", quoted(c.id), quoted(c.scene), quoted(c.technique),
                           quoted(c.params_summary), c.resolution.width, c.resolution.height, c.ok ? 1 : 0,
                           c.gpu_frame.stats.median, c.gpu_frame.stats.min, c.gpu_frame.stats.mean, c.gpu_frame.stats.mad,
                           c.gpu_frame.stats.cv, c.wall.stats.median, c.wall.stats.mad, c.wall.stats.cv);
        const Estimate& r = c.ratio.estimate;
        out += c.ratio.measured() ? fmt::format(",{},{},{},{}", c.cpu.stats.median, r.value, r.ci.low, r.ci.high)
                                  : fmt::format(",{},,,", c.cpu.stats.median);
        out += fmt::format(",{},{}", c.gpu_frame.stats.count, run.frames_per_sample);
        for (const auto& name : pass_names) {
            const TimingSeries* pass = nullptr;
            for (const auto& p : c.passes)
                if (p.name == name) pass = &p;
            out += pass ? fmt::format(",{},{}", pass->stats.median, pass->stats.mad) : std::string(",,");
        }
        out += fmt::format(",{},{},{},{},{},{}", c.memory.technique_bytes, c.memory.target_bytes, c.memory.scene_bytes,
                           c.triangles, quoted(c.shadow_sampler), c.nonfinite_pixels);
        for (const MetricInfo& metric : metrics) {
            const auto& m = c.image_error;
            out += m ? value_or_na((*m).*metric.value, group_declared(metric.group, m->columns)) : std::string(",");
        }
        out += fmt::format(",{},{}\n", quoted(run.environment.device.name), quoted(run.environment.git_commit));
    }
    return out;
}

void write_csv_report(const std::filesystem::path& path, const RunRecord& run) {
    write_text_atomically(path, csv_report(run));
}

}  // namespace canopy
