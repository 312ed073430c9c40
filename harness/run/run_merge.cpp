#include "run/run_merge.hpp"

#include "core/error.hpp"
#include "report/atomic_file.hpp"
#include "run/case_labels.hpp"
#include "run/experiment_runner.hpp"
#include "run/run_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>

namespace canopy {

namespace fs = std::filesystem;

namespace {

// Identity fields every shard of one run shares; the hostname and load may differ, the rest not.
std::vector<std::string> differences(const RunRecord& first, const RunRecord& other) {
    std::vector<std::string> out;
    for (const auto& [name, value] : first.identity.fields) {
        if (name == "shard") continue;
        const std::string* theirs = other.identity.find(name);
        if (!theirs || *theirs != value)
            out.push_back(fmt::format("{}: '{}' against '{}'", name, value, theirs ? *theirs : std::string("(none)")));
    }
    const Environment &a = first.environment, &b = other.environment;
    if (a.git_commit != b.git_commit || a.git_dirty != b.git_dirty)
        out.push_back(fmt::format("commit: {}{} against {}{}", a.git_commit, a.git_dirty ? " (dirty)" : "", b.git_commit,
                                  b.git_dirty ? " (dirty)" : ""));
    if (a.build_type != b.build_type) out.push_back(fmt::format("build: {} against {}", a.build_type, b.build_type));
    return out;
}

}  // namespace

MergedRun merge_shards(const std::vector<RunRecord>& shards, const std::vector<fs::path>& folders,
                       const Experiment& experiment, const std::vector<Case>& cases, const TechniqueRegistry& registry) {
    if (shards.empty()) throw ConfigError(fs::path(), 0, "no shard to merge", "give the shards' run folders");
    std::set<std::string> seen;
    size_t count = 0;
    for (size_t k = 0; k < shards.size(); ++k) {
        const RunRecord& s = shards[k];
        if (s.shard.empty())
            throw ConfigError(folders[k], 0, "this run is not a shard (it was not run with --shard i/N)",
                              "merge the folders of `canopy run --shard` runs only");
        if (s.experiment != experiment.name || s.environment.config_hash != experiment.config_hash)
            throw ConfigError(folders[k], 0,
                              fmt::format("a shard of {} (config hash {}), not of {} (config hash {})", s.experiment,
                                          s.environment.config_hash, experiment.name, experiment.config_hash),
                              "merge shards of one experiment, run with the config as it is now");
        const ShardSpec spec = parse_shard(s.shard);
        if (k == 0) count = spec.count;
        if (spec.count != count)
            throw ConfigError(folders[k], 0, fmt::format("shard {} of another split than {}/{}", s.shard, 1, count),
                              "merge shards of one `--shard i/N` split");
        if (!seen.insert(s.shard).second)
            throw ConfigError(folders[k], 0, fmt::format("shard {} is given twice", s.shard), "give each shard's folder once");
        const std::vector<std::string> diff = differences(shards[0], s);
        if (!diff.empty()) {
            std::string lines;
            for (const std::string& d : diff) lines += "\n    " + d;
            throw ConfigError(folders[k], 0,
                              fmt::format("shard {} was not measured like shard {} ({}):{}", s.shard, shards[0].shard,
                                          folders[0].string(), lines),
                              "merge shards run by one canopy build of one commit, on one kind of device, with the same "
                              "options; rerun the odd one");
        }
    }

    // Shards in shard order, whatever the order given: the merge is the same.
    std::vector<size_t> order(shards.size());
    for (size_t k = 0; k < shards.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return parse_shard(shards[a].shard).index < parse_shard(shards[b].shard).index; });

    MergedRun merged;
    RunRecord& run = merged.run;
    const RunRecord& first = shards[order.front()];
    run.experiment = first.experiment;
    run.description = first.description;
    run.config_file = first.config_file;
    run.environment = first.environment;
    run.warmup_frames = first.warmup_frames;
    run.rounds = first.rounds;
    run.frames_per_sample = first.frames_per_sample;
    run.camera_path = first.camera_path;
    run.distance_bands = first.distance_bands;
    run.quick = first.quick;
    run.reference_enabled = first.reference_enabled;
    for (const auto& field : first.identity.fields)
        if (field.first != "shard") run.identity.fields.push_back(field);
    run.planned_cases = cases.size();
    run.started_at = first.started_at;
    run.finished_at = first.finished_at;

    bool all_complete = true;
    for (size_t k : order) {
        const RunRecord& s = shards[k];
        std::vector<std::string> groups;
        for (const GroupRecord& g : s.groups) groups.push_back(g.name);
        run.merged_from.push_back({s.shard, s.environment.hostname, s.started_at, s.finished_at, s.cases.size(), groups});
        run.started_at = std::min(run.started_at, s.started_at);
        run.finished_at = std::max(run.finished_at, s.finished_at);
        all_complete = all_complete && s.status == "complete";
    }

    // Every case by id, from the shard that measured it.
    std::map<std::string, const CaseResult*> measured;
    std::map<std::string, std::string> node_of;  // case id -> the hostname of the shard that measured it
    std::map<std::string, const GroupRecord*> groups_by_name;
    std::vector<const ReferenceRecord*> references;
    for (size_t k : order) {
        const RunRecord& s = shards[k];
        for (const CaseResult& c : s.cases) {
            measured.emplace(c.id, &c);
            node_of.emplace(c.id, s.environment.hostname);
        }
        for (const GroupRecord& g : s.groups)
            if (!g.chunks.empty()) groups_by_name.emplace(g.name, &g);
        for (const ReferenceRecord& r : s.references) references.push_back(&r);
    }
    const CaseLabels labels(cases, registry);
    for (const PlannedGroup& planned : plan_groups(cases, experiment.scenes)) {
        const auto group = groups_by_name.find(planned.name);
        const bool recorded = group != groups_by_name.end();
        if (recorded) run.groups.push_back(*group->second);
        // The group's reference, in the groups' order as a single run records them.
        const std::string& scene = experiment.scenes[planned.scene_index].name;
        for (const ReferenceRecord* r : references) {
            const bool same = r->scene == scene && r->resolution.width == planned.resolution.width &&
                              r->resolution.height == planned.resolution.height;
            const bool known = std::any_of(run.references.begin(), run.references.end(), [&](const ReferenceRecord& have) {
                return have.scene == r->scene && have.resolution.width == r->resolution.width &&
                       have.resolution.height == r->resolution.height;
            });
            if (same && !known) run.references.push_back(*r);
        }
        for (size_t i : planned.cases) {
            const Case& c = cases[i];
            const auto found = measured.find(c.id);
            if (!recorded || found == measured.end()) {
                merged.missing.push_back(c.id);
                continue;
            }
            CaseResult result = *found->second;
            result.group = run.groups.size() - 1;
            result.node = node_of.at(c.id);
            result.params = c.params.values();
            result.params_summary = c.params.summary();
            result.params_shown = labels.parameters(c);
            run.cases.push_back(std::move(result));
        }
    }
    const bool any_failed = std::any_of(run.cases.begin(), run.cases.end(), [](const CaseResult& c) { return !c.ok; });
    if (!merged.missing.empty()) {
        run.status = "interrupted";
        run.error = fmt::format("{} of {} cases are in no shard given to canopy merge (first: {})", merged.missing.size(),
                                cases.size(), merged.missing.front());
    } else {
        run.status = any_failed ? "failed" : all_complete ? "complete" : "interrupted";
    }
    return merged;
}

size_t copy_shard_images(const MergedRun& merged, const std::vector<RunRecord>& shards, const std::vector<fs::path>& folders,
                         const fs::path& out) {
    // Where each file the merged record names lies: the first shard that has it.
    const auto source_of = [&](const std::string& relative) -> fs::path {
        for (size_t k = 0; k < shards.size(); ++k)
            if (std::error_code e; fs::is_regular_file(folders[k] / relative, e)) return folders[k] / relative;
        return {};
    };
    std::vector<std::string> files;
    for (const CaseResult& c : merged.run.cases)
        for (const std::string* f : {&c.image_exr, &c.image_png, &c.visibility_exr, &c.error_map_png, &c.flip_map_png})
            if (!f->empty()) files.push_back(*f);
    for (const ReferenceRecord& r : merged.run.references)
        for (const std::string* f : {&r.image_exr, &r.image_png, &r.visibility_exr, &r.pixel_visibility_exr})
            if (!f->empty()) files.push_back(*f);
    size_t copied = 0;
    for (const std::string& relative : files) {
        const fs::path from = source_of(relative);
        if (from.empty())
            throw ConfigError(fs::path(relative), 0, "an image the shards' results.json names is in none of their folders",
                              "merge the shards' folders as `canopy run --shard` left them");
        const fs::path to = out / relative;
        fs::create_directories(to.parent_path());
        const fs::path partial = temporary_path(to);  // renamed into place: no half-copied image
        fs::copy_file(from, partial, fs::copy_options::overwrite_existing);
        fs::rename(partial, to);
        ++copied;
    }
    return copied;
}

}  // namespace canopy
