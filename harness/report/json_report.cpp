#include "report/json_report.hpp"

#include "metrics/metric_registry.hpp"
#include "reference/reference_noise.hpp"
#include "report/atomic_file.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <map>

namespace canopy {

namespace {

nlohmann::json param_json(const ParamValue& value) {
    return std::visit([](const auto& v) { return nlohmann::json(v); }, value);
}

nlohmann::json stats_json(const SampleStats& s) {
    return {{"count", s.count}, {"median", s.median}, {"min", s.min}, {"max", s.max},
            {"mean", s.mean},   {"mad", s.mad},       {"cv", s.cv}};
}

nlohmann::json series_json(const TimingSeries& t) {
    return {{"name", t.name}, {"stats_ms", stats_json(t.stats)}, {"samples_ms", t.samples_ms}};
}

// NaN (not applicable) and infinities (PSNR of identical images) become null in JSON.
nlohmann::json metric(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr); }

// Every registered metric and count (metrics/metric_registry.hpp) under its name, and the
// groups the technique declares meaningful (the others are null and read "n/a").
nlohmann::json error_json(const ImageMetrics& m) {
    nlohmann::json j = nlohmann::json::object();
    for (const MetricInfo& info : registered_metrics()) {
        const double value = m.*info.value;
        j[std::string(info.name)] = metric(value);
        if (!info.infinite_key.empty()) j[std::string(info.infinite_key)] = std::isinf(value) && value > 0;
    }
    for (const MetricCountInfo& count : registered_metric_counts()) j[std::string(count.name)] = m.*count.value;
    j["max_error_pixel"] = {m.max_x, m.max_y};  // where max_error is: a place, not a metric
    nlohmann::json columns = nlohmann::json::object();
    for (const MetricGroupInfo& group : metric_groups())
        if (group.declared) columns[std::string(group.key)] = m.columns.*group.declared;
    j["columns"] = columns;
    return j;
}

nlohmann::json reference_json(const ReferenceRecord& r) {
    return {{"scene", r.scene},
            {"width", r.resolution.width},
            {"height", r.resolution.height},
            {"key", r.key},
            {"from_cache", r.from_cache},
            {"seconds", r.seconds},
            {"shadow_rays", r.shadow_rays},
            {"light_samples", r.light_samples},
            {"pixel_samples", r.pixel_samples},
            {"error_map_scale", r.error_map_scale},
            {"degenerate", r.degenerate},
            {"pixel_visibility",
             {{"key", r.pixel_visibility_key},
              {"from_cache", r.pixel_visibility_from_cache},
              {"seconds", r.pixel_visibility_seconds},
              {"shadow_rays", r.pixel_visibility_shadow_rays},
              {"light_samples", r.pixel_visibility_samples}}},
            {"images",
             {{"exr", r.image_exr},
              {"png", r.image_png},
              {"visibility_exr", r.visibility_exr},
              {"pixel_visibility_exr", r.pixel_visibility_exr}}}};
}

nlohmann::json ratio_json(const RatioRecord& r) {
    if (!r.measured()) return nullptr;
    return {{"median", metric(r.estimate.value)},
            {"ci95_low", metric(r.estimate.ci.low)},
            {"ci95_high", metric(r.estimate.ci.high)},
            {"per_round", r.per_round}};
}

nlohmann::json group_json(const GroupRecord& g) {
    nlohmann::json chunks = nlohmann::json::array();
    for (const MeasurementChunk& c : g.chunks)
        chunks.push_back({{"cases", c.cases},
                          {"started_at", c.started_at},
                          {"seconds", c.seconds},
                          {"orders", c.orders},
                          {"baseline_gpu_ms", c.baseline_gpu_ms}});
    return {{"name", g.name},
            {"scene", g.scene},
            {"width", g.resolution.width},
            {"height", g.resolution.height},
            {"baseline", g.cases.empty() ? std::string() : g.baseline()},
            {"cases", g.cases},
            {"chunks", chunks}};
}

nlohmann::json series_list_json(const std::vector<TimingSeries>& list) {
    nlohmann::json j = nlohmann::json::array();
    for (const TimingSeries& t : list) j.push_back(series_json(t));
    return j;
}

nlohmann::json timing_check_json(const TimingCheck& t) {
    if (!t.checked) return nullptr;
    return {{"pass_sum_ms", t.pass_sum_ms},
            {"wall_ms", t.wall_ms},
            {"gap_ms", t.gap_ms},
            {"tolerance_ms", t.tolerance_ms},
            {"agrees", t.agrees()}};
}

nlohmann::json path_frames_json(const std::vector<CaseResult::PathFrame>& frames) {
    nlohmann::json j = nlohmann::json::array();
    for (const CaseResult::PathFrame& f : frames)
        j.push_back({{"gpu_frame", series_json(f.gpu_frame)}, {"passes", series_list_json(f.passes)}});
    return j;
}

nlohmann::json camera_path_json(const std::optional<CameraPath>& path) {
    if (!path) return nullptr;
    nlohmann::json poses = nlohmann::json::array();
    for (const CameraPose& p : path->poses)
        poses.push_back({{"position", {p.position.x, p.position.y, p.position.z}},
                         {"target", {p.target.x, p.target.y, p.target.z}},
                         {"fov", p.fov_y_degrees}});
    return {{"frames", path->frames}, {"poses", poses}, {"popping", path->popping}};
}

// The load phase: each pass's GPU time, in order, and the phase's totals.
nlohmann::json load_json(const CaseResult::LoadPhase& load) {
    nlohmann::json passes = nlohmann::json::array();
    for (const auto& [name, ms] : load.pass_gpu_ms) passes.push_back({{"name", name}, {"gpu_ms", ms}});
    return {{"passes", passes}, {"gpu_ms", load.gpu_ms}, {"wall_ms", load.wall_ms}, {"uploaded_bytes", load.uploaded_bytes}};
}

// The CPU passes' counts, in the order first counted (an array: JSON objects have no order).
nlohmann::json counters_json(const std::vector<std::pair<std::string, double>>& counters) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& [name, value] : counters) out.push_back({{"name", name}, {"value", value}});
    return out;
}

// The noise this reference induces in each metric: the largest spread over its noisy replicates
// (reference/reference_noise.hpp) among the cases compared with it. Derived from the cases'
// reference_replicates, so the reader does not read it back.
nlohmann::json reference_metric_noise(const RunRecord& run, const ReferenceRecord& r) {
    std::map<std::string, double> largest;
    for (const CaseResult& c : run.cases) {
        if (c.scene != r.scene || c.resolution.width != r.resolution.width || c.resolution.height != r.resolution.height)
            continue;
        for (const auto& [name, values] : c.reference_replicates) {
            const double spread = replicate_spread(values);
            if (std::isfinite(spread)) largest[name] = std::max(largest.count(name) ? largest[name] : 0.0, spread);
        }
    }
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [name, spread] : largest) j[name] = spread;
    return j;
}

// Non-finite replicate values are written null, as the metrics are.
nlohmann::json replicates_json(const std::map<std::string, std::vector<double>>& replicates) {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [name, values] : replicates) {
        nlohmann::json list = nlohmann::json::array();
        for (double v : values) list.push_back(std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr));
        j[name] = list;
    }
    return j;
}

nlohmann::json case_json(const CaseResult& c) {
    nlohmann::json params = nlohmann::json::object();
    for (const auto& [name, value] : c.params) params[name] = param_json(value);
    const nlohmann::json passes = series_list_json(c.passes);
    return {{"id", c.id},
            {"scene", c.scene},
            {"scene_variant", c.scene_variant},
            {"technique", c.technique},
            {"width", c.resolution.width},
            {"height", c.resolution.height},
            {"params", params},
            {"ok", c.ok},
            {"error", c.error},
            {"group", c.group},
            {"chunk", c.chunk},
            {"node", c.node},
            {"group_baseline", c.group_baseline},
            {"ratio", ratio_json(c.ratio)},
            {"timing",
             {{"gpu_frame", series_json(c.gpu_frame)},
              {"wall", series_json(c.wall)},
              {"cpu", series_json(c.cpu)},
              {"passes", passes},
              {"cpu_passes", series_list_json(c.cpu_passes)},
              {"record_cpu", series_json(c.record_cpu)},
              {"timing_check", timing_check_json(c.timing_check)},
              {"path_frames", path_frames_json(c.path_frames)},
              {"sample_start_s", c.sample_start_s}}},
            {"load", load_json(c.load)},
            {"memory_bytes",
             {{"technique", c.memory.technique_bytes},
              {"technique_peak", c.memory.technique_peak_bytes},
              {"targets", c.memory.target_bytes},
              {"scene", c.memory.scene_bytes}}},
            {"triangles", c.triangles},
            {"primitives", c.primitives ? nlohmann::json{{"submitted", c.primitives->submitted},
                                                         {"rasterised", c.primitives->rasterised}}
                                        : nlohmann::json(nullptr)},
            {"counters", counters_json(c.counters)},
            {"popping_per_pair", c.popping_per_pair},
            {"shadow_sampler", c.shadow_sampler},
            {"nonfinite_pixels", c.nonfinite_pixels},
            {"image_error", c.image_error ? error_json(*c.image_error) : nlohmann::json(nullptr)},
            {"reference_replicates", replicates_json(c.reference_replicates)},
            {"images", {{"exr", c.image_exr}, {"png", c.image_png}, {"visibility_exr", c.visibility_exr},
                        {"error_map_png", c.error_map_png}, {"flip_map_png", c.flip_map_png}}}};
}

}  // namespace

std::string json_report(const RunRecord& run) {
    nlohmann::json cases = nlohmann::json::array();
    for (const auto& c : run.cases) cases.push_back(case_json(c));
    nlohmann::json groups = nlohmann::json::array();
    for (const auto& g : run.groups) groups.push_back(group_json(g));
    nlohmann::json references = nlohmann::json::array();
    for (const auto& r : run.references) {
        nlohmann::json reference = reference_json(r);
        reference["metric_noise"] = reference_metric_noise(run, r);
        references.push_back(std::move(reference));
    }
    nlohmann::json merged_from = nlohmann::json::array();
    for (const auto& m : run.merged_from)
        merged_from.push_back({{"shard", m.shard}, {"hostname", m.hostname}, {"started_at", m.started_at},
                               {"finished_at", m.finished_at}, {"cases", m.cases}, {"groups", m.groups}});
    nlohmann::json identity = nlohmann::json::object();
    for (const auto& [name, value] : run.identity.fields) identity[name] = value;
    nlohmann::json inputs = nlohmann::json::array();
    for (const InputFile& f : run.inputs) inputs.push_back({{"file", f.file}, {"fnv1a_64", f.hash}});
    nlohmann::json j = {{"canopy_results_version", kResultsVersion},
                        {"experiment", run.experiment},
                        {"description", run.description},
                        {"config", run.config_file},
                        {"inputs", inputs},
                        {"status", run.status},
                        {"error", run.error},
                        {"run_identity", identity},
                        {"started_at", run.started_at},
                        {"finished_at", run.finished_at},
                        {"resumed_at", run.resumed_at},
                        {"warmup_frames", run.warmup_frames},
                        {"rounds", run.rounds},
                        {"frames_per_sample", run.frames_per_sample},
                        {"measured_frames", run.measured_frames()},
                        {"camera_path", camera_path_json(run.camera_path)},
                        {"distance_bands", run.distance_bands ? nlohmann::json::array({run.distance_bands->middle_from,
                                                                                       run.distance_bands->far_from})
                                                              : nlohmann::json()},
                        {"quick", run.quick},
                        {"shard", run.shard},
                        {"merged_from", merged_from},
                        {"planned_cases", run.planned_cases},
                        {"environment", run.environment},
                        {"reference_enabled", run.reference_enabled},
                        {"references", references},
                        {"groups", groups},
                        {"cases", cases}};
    return j.dump(2) + "\n";
}

void write_json_report(const std::filesystem::path& path, const RunRecord& run) {
    write_text_atomically(path, json_report(run));
}

}  // namespace canopy
