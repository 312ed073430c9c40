#include "report/json_report.hpp"

#include "report/atomic_file.hpp"

#include <nlohmann/json.hpp>

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

nlohmann::json case_json(const CaseResult& c) {
    nlohmann::json params = nlohmann::json::object();
    for (const auto& [name, value] : c.params) params[name] = param_json(value);
    nlohmann::json passes = nlohmann::json::array();
    for (const auto& p : c.passes) passes.push_back(series_json(p));
    return {{"id", c.id},
            {"scene", c.scene},
            {"technique", c.technique},
            {"width", c.resolution.width},
            {"height", c.resolution.height},
            {"params", params},
            {"ok", c.ok},
            {"error", c.error},
            {"timing", {{"gpu_frame", series_json(c.gpu_frame)}, {"wall", series_json(c.wall)}, {"passes", passes}}},
            {"memory_bytes",
             {{"technique", c.memory.technique_bytes}, {"targets", c.memory.target_bytes}, {"scene", c.memory.scene_bytes}}},
            {"triangles", c.triangles},
            {"shadow_sampler", c.shadow_sampler},
            {"nonfinite_pixels", c.nonfinite_pixels},
            {"images", {{"exr", c.image_exr}, {"png", c.image_png}}}};
}

}  // namespace

std::string json_report(const RunRecord& run) {
    nlohmann::json cases = nlohmann::json::array();
    for (const auto& c : run.cases) cases.push_back(case_json(c));
    nlohmann::json j = {{"canopy_results_version", 1},
                        {"experiment", run.experiment},
                        {"description", run.description},
                        {"config", run.config_file},
                        {"status", run.status},
                        {"started_at", run.started_at},
                        {"finished_at", run.finished_at},
                        {"warmup_frames", run.warmup_frames},
                        {"measured_frames", run.measured_frames},
                        {"quick", run.quick},
                        {"planned_cases", run.planned_cases},
                        {"environment", run.environment},
                        {"cases", cases}};
    return j.dump(2) + "\n";
}

void write_json_report(const std::filesystem::path& path, const RunRecord& run) {
    write_text_atomically(path, json_report(run));
}

}  // namespace canopy
