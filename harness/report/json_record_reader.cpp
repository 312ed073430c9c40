#include "report/json_record_reader.hpp"

#include "metrics/metric_registry.hpp"
#include "report/json_report.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <limits>
#include <stdexcept>

namespace canopy {

namespace {

using nlohmann::json;

constexpr double kAbsent = std::numeric_limits<double>::quiet_NaN();

// null (not applicable, or not finite) reads back as NaN.
double metric(const json& value) { return value.is_null() ? kAbsent : value.get<double>(); }

SampleStats read_stats(const json& j) {
    SampleStats s;
    s.count = j.at("count").get<size_t>();
    s.median = j.at("median").get<double>();
    s.min = j.at("min").get<double>();
    s.max = j.at("max").get<double>();
    s.mean = j.at("mean").get<double>();
    s.mad = j.at("mad").get<double>();
    s.cv = j.at("cv").get<double>();
    return s;
}

TimingSeries read_series(const json& j) {
    return {j.at("name").get<std::string>(), j.at("samples_ms").get<std::vector<double>>(), read_stats(j.at("stats_ms"))};
}

ParamValue read_param(const json& j) {
    if (j.is_boolean()) return j.get<bool>();
    if (j.is_number_integer()) return j.get<long long>();
    if (j.is_number()) return j.get<double>();
    return j.get<std::string>();
}

// Every registered metric and count (metrics/metric_registry.hpp). A metric added to canopy after
// the file was written is missing from it and reads as NaN: not measured.
ImageMetrics read_error(const json& j) {
    ImageMetrics m{};
    for (const MetricInfo& info : registered_metrics()) {
        const std::string name(info.name);
        if (!info.infinite_key.empty() && j.value(std::string(info.infinite_key), false))
            m.*info.value = std::numeric_limits<double>::infinity();
        else
            m.*info.value = j.contains(name) ? metric(j.at(name)) : kAbsent;
    }
    for (const MetricCountInfo& count : registered_metric_counts()) {
        const std::string name(count.name);
        m.*count.value = j.contains(name) ? j.at(name).get<long long>() : 0;
    }
    m.max_x = j.at("max_error_pixel").at(0).get<int>();
    m.max_y = j.at("max_error_pixel").at(1).get<int>();
    for (const MetricGroupInfo& group : metric_groups())
        // A group newer than the file was not declared by it (its metrics read as NaN above).
        if (group.declared) m.columns.*group.declared = j.at("columns").value(std::string(group.key), false);
    return m;
}

RatioRecord read_ratio(const json& j) {
    RatioRecord r;
    if (j.is_null()) return r;
    r.per_round = j.at("per_round").get<std::vector<double>>();
    r.estimate = {metric(j.at("median")), {metric(j.at("ci95_low")), metric(j.at("ci95_high"))}, r.per_round.size()};
    return r;
}

GroupRecord read_group(const json& j) {
    GroupRecord g;
    g.name = j.at("name").get<std::string>();
    g.scene = j.at("scene").get<std::string>();
    g.resolution = {j.at("width").get<int>(), j.at("height").get<int>()};
    g.cases = j.at("cases").get<std::vector<std::string>>();
    for (const json& c : j.at("chunks")) {
        MeasurementChunk chunk;
        chunk.cases = c.at("cases").get<std::vector<std::string>>();
        chunk.started_at = c.at("started_at").get<std::string>();
        chunk.seconds = c.at("seconds").get<double>();
        chunk.orders = c.at("orders").get<std::vector<std::vector<size_t>>>();
        chunk.baseline_gpu_ms = c.at("baseline_gpu_ms").get<std::vector<double>>();
        g.chunks.push_back(std::move(chunk));
    }
    return g;
}

CaseResult read_case(const json& j) {
    CaseResult c;
    c.id = j.at("id").get<std::string>();
    c.scene = j.at("scene").get<std::string>();
    c.scene_variant = j.value("scene_variant", std::string());  // absent in files older than the key
    c.technique = j.at("technique").get<std::string>();
    c.resolution = {j.at("width").get<int>(), j.at("height").get<int>()};
    for (const auto& [name, value] : j.at("params").items()) c.params.emplace_back(name, read_param(value));
    c.ok = j.at("ok").get<bool>();
    c.error = j.at("error").get<std::string>();
    c.group = j.at("group").get<size_t>();
    c.chunk = j.at("chunk").get<size_t>();
    c.node = j.value("node", "");  // absent in files older than the key
    c.group_baseline = j.at("group_baseline").get<bool>();
    c.ratio = read_ratio(j.at("ratio"));
    const json& timing = j.at("timing");
    c.gpu_frame = read_series(timing.at("gpu_frame"));
    c.wall = read_series(timing.at("wall"));
    c.cpu = read_series(timing.at("cpu"));
    c.sample_start_s = timing.at("sample_start_s").get<std::vector<double>>();
    for (const json& pass : timing.at("passes")) c.passes.push_back(read_series(pass));
    // Written since results version 3 gained them: absent from older files.
    if (timing.contains("cpu_passes"))
        for (const json& pass : timing.at("cpu_passes")) c.cpu_passes.push_back(read_series(pass));
    if (timing.contains("record_cpu")) c.record_cpu = read_series(timing.at("record_cpu"));
    if (timing.contains("timing_check") && !timing.at("timing_check").is_null()) {
        const json& t = timing.at("timing_check");
        c.timing_check = {true, t.at("pass_sum_ms").get<double>(), t.at("wall_ms").get<double>(),
                          t.at("gap_ms").get<double>(), t.at("tolerance_ms").get<double>()};
    }
    if (timing.contains("path_frames"))
        for (const json& f : timing.at("path_frames")) {
            CaseResult::PathFrame frame;
            frame.gpu_frame = read_series(f.at("gpu_frame"));
            for (const json& pass : f.at("passes")) frame.passes.push_back(read_series(pass));
            c.path_frames.push_back(std::move(frame));
        }
    if (j.contains("load")) {  // absent in results.json written before the load phase was recorded
        const json& load = j.at("load");
        for (const json& pass : load.at("passes"))
            c.load.pass_gpu_ms.emplace_back(pass.at("name").get<std::string>(), pass.at("gpu_ms").get<double>());
        c.load.gpu_ms = load.at("gpu_ms").get<double>();
        c.load.wall_ms = load.at("wall_ms").get<double>();
        c.load.uploaded_bytes = load.at("uploaded_bytes").get<uint64_t>();
    }
    const json& memory = j.at("memory_bytes");
    c.memory = {memory.at("technique").get<uint64_t>(), memory.at("targets").get<uint64_t>(),
                memory.at("scene").get<uint64_t>()};
    // Absent in results.json written before the load phase's resources were released: they were
    // held all along, so the peak is what the frames held.
    c.memory.technique_peak_bytes = memory.value("technique_peak", c.memory.technique_bytes);
    c.triangles = j.at("triangles").get<size_t>();
    // Absent in results.json written before frames counted their triangles.
    if (j.contains("primitives") && !j.at("primitives").is_null())
        c.primitives = PrimitiveCounts{j.at("primitives").at("submitted").get<uint64_t>(),
                                       j.at("primitives").at("rasterised").get<uint64_t>()};
    if (j.contains("popping_per_pair"))  // absent in results.json written before the curve was kept
        for (const json& v : j.at("popping_per_pair"))  // a pair with no finite pixel is NaN, written null
            c.popping_per_pair.push_back(v.is_null() ? std::numeric_limits<double>::quiet_NaN() : v.get<double>());
    if (j.contains("counters"))  // absent in results.json written before CPU passes counted
        for (const json& counter : j.at("counters"))
            c.counters.emplace_back(counter.at("name").get<std::string>(),
                                    counter.at("value").is_null() ? std::numeric_limits<double>::quiet_NaN()
                                                                  : counter.at("value").get<double>());
    c.shadow_sampler = j.at("shadow_sampler").get<std::string>();
    c.nonfinite_pixels = j.at("nonfinite_pixels").get<long long>();
    if (!j.at("image_error").is_null()) c.image_error = read_error(j.at("image_error"));
    if (j.contains("reference_replicates"))  // absent in results.json written before the reference's noise was measured
        for (const auto& [name, values] : j.at("reference_replicates").items())
            for (const json& v : values)
                c.reference_replicates[name].push_back(v.is_null() ? std::numeric_limits<double>::quiet_NaN()
                                                                   : v.get<double>());
    const json& images = j.at("images");
    c.image_exr = images.at("exr").get<std::string>();
    c.image_png = images.at("png").get<std::string>();
    c.visibility_exr = images.at("visibility_exr").get<std::string>();
    c.error_map_png = images.at("error_map_png").get<std::string>();
    c.flip_map_png = images.at("flip_map_png").get<std::string>();
    return c;
}

ReferenceRecord read_reference(const json& j) {
    ReferenceRecord r;
    r.scene = j.at("scene").get<std::string>();
    r.resolution = {j.at("width").get<int>(), j.at("height").get<int>()};
    r.key = j.at("key").get<std::string>();
    r.from_cache = j.at("from_cache").get<bool>();
    r.seconds = j.at("seconds").get<double>();
    r.shadow_rays = j.at("shadow_rays").get<uint64_t>();
    r.light_samples = j.at("light_samples").get<int>();
    r.pixel_samples = j.at("pixel_samples").get<int>();
    r.error_map_scale = j.at("error_map_scale").get<double>();
    if (j.contains("degenerate")) r.degenerate = j.at("degenerate").get<std::vector<std::string>>();
    const json& pixel_visibility = j.at("pixel_visibility");
    r.pixel_visibility_key = pixel_visibility.at("key").get<std::string>();
    r.pixel_visibility_from_cache = pixel_visibility.at("from_cache").get<bool>();
    r.pixel_visibility_seconds = pixel_visibility.at("seconds").get<double>();
    r.pixel_visibility_shadow_rays = pixel_visibility.at("shadow_rays").get<uint64_t>();
    r.pixel_visibility_samples = pixel_visibility.at("light_samples").get<int>();
    const json& images = j.at("images");
    r.image_exr = images.at("exr").get<std::string>();
    r.image_png = images.at("png").get<std::string>();
    r.visibility_exr = images.at("visibility_exr").get<std::string>();
    r.pixel_visibility_exr = images.at("pixel_visibility_exr").get<std::string>();
    return r;
}

}  // namespace

RunRecord read_json_report(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error(fmt::format("cannot read {}: it does not exist or cannot be opened", file.string()));
    try {
        const json j = json::parse(in);
        const int version = j.at("canopy_results_version").get<int>();
        if (version != kResultsVersion)
            throw std::runtime_error(fmt::format("it is results version {}, this canopy reads version {}", version,
                                                 kResultsVersion));
        RunRecord run;
        run.experiment = j.at("experiment").get<std::string>();
        run.description = j.at("description").get<std::string>();
        run.config_file = j.at("config").get<std::string>();
        run.status = j.at("status").get<std::string>();
        run.error = j.at("error").get<std::string>();
        for (const auto& [name, value] : j.at("run_identity").items())
            run.identity.fields.emplace_back(name, value.get<std::string>());
        run.started_at = j.at("started_at").get<std::string>();
        run.finished_at = j.at("finished_at").get<std::string>();
        run.resumed_at = j.at("resumed_at").get<std::vector<std::string>>();
        run.warmup_frames = j.at("warmup_frames").get<int>();
        run.rounds = j.at("rounds").get<int>();
        run.frames_per_sample = j.at("frames_per_sample").get<int>();
        run.quick = j.at("quick").get<bool>();
        run.shard = j.value("shard", "");  // absent in files older than the key
        if (j.contains("merged_from"))
            for (const json& m : j.at("merged_from"))
                run.merged_from.push_back({m.at("shard").get<std::string>(), m.at("hostname").get<std::string>(),
                                           m.at("started_at").get<std::string>(), m.at("finished_at").get<std::string>(),
                                           m.at("cases").get<size_t>(),
                                           m.value("groups", std::vector<std::string>{})});
        if (j.contains("camera_path") && !j.at("camera_path").is_null()) {
            const json& path = j.at("camera_path");
            CameraPath p;
            p.frames = path.at("frames").get<int>();
            p.popping = path.value("popping", false);  // false in a file older than the key
            for (const json& pose : path.at("poses")) {
                const auto v = [&](const char* key) {
                    const auto a = pose.at(key).get<std::vector<float>>();
                    return glm::vec3(a.at(0), a.at(1), a.at(2));
                };
                p.poses.push_back({v("position"), v("target"), pose.at("fov").get<float>()});
            }
            run.camera_path = std::move(p);
        }
        if (j.contains("distance_bands") && !j.at("distance_bands").is_null())  // absent in files older than the key
            run.distance_bands = DistanceBands{j.at("distance_bands").at(0).get<double>(), j.at("distance_bands").at(1).get<double>()};
        if (j.contains("inputs"))  // absent in files older than the key
            for (const json& f : j.at("inputs"))
                run.inputs.push_back({f.at("file").get<std::string>(), f.at("fnv1a_64").get<std::string>()});
        run.planned_cases = j.at("planned_cases").get<size_t>();
        run.reference_enabled = j.at("reference_enabled").get<bool>();
        run.environment = j.at("environment").get<Environment>();
        for (const json& r : j.at("references")) run.references.push_back(read_reference(r));
        for (const json& g : j.at("groups")) run.groups.push_back(read_group(g));
        for (const json& c : j.at("cases")) run.cases.push_back(read_case(c));
        return run;
    } catch (const json::exception& e) {
        throw std::runtime_error(fmt::format("cannot read {}: not a canopy results.json ({})", file.string(), e.what()));
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(fmt::format("cannot read {}: {}", file.string(), e.what()));
    }
}

}  // namespace canopy
