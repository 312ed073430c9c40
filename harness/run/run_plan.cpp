#include "run/run_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <stdexcept>

namespace canopy {

std::string case_key(const Case& c, const Scene& scene) {
    std::string text = scene.name + '\n' + c.technique + '\n';
    for (const auto& [name, value] : c.params.values()) text += name + '=' + to_string(value) + '\n';
    text += fmt::format("{}x{}", c.resolution.width, c.resolution.height);
    uint64_t hash = 14695981039346656037ull;
    for (unsigned char ch : text) {
        hash ^= ch;
        hash *= 1099511628211ull;
    }
    return fmt::format("{:016x}", hash);
}

double estimated_case_cost(const Case& c, const Technique& technique, const MeasurementSettings& settings,
                           bool group_baseline) {
    const FrameGraph graph = technique.graph(c.params);
    const double screen = double(c.resolution.width) * double(c.resolution.height);
    const auto pixels = [&](const ImageDecl& image) {
        if (image.extent.rule == ImageExtent::Rule::screen) {
            const double d = std::max(1u, image.extent.divisor);
            return screen / (d * d) * image.layers;
        }
        return double(image.extent.width) * double(image.extent.height) * image.layers;
    };
    double per_frame = screen;  // the harness's own camera targets
    for (const PassDecl& pass : graph.passes) {
        if (pass.phase != Phase::frame) continue;
        double largest = 0;
        for (const ResourceUse& use : pass.uses)
            if (const ImageDecl* image = graph.image(use.resource)) largest = std::max(largest, pixels(*image));
        per_frame += largest > 0 ? largest : 0.1 * screen;
    }
    const double measured = double(settings.rounds) * double(settings.frames_per_sample);
    // Each sample of a non-baseline case sits between two of the baseline's (adjacent pairing).
    const double frames = double(settings.warmup_frames) + measured * (group_baseline ? 1.0 : 2.0);
    return frames * per_frame / 1e6;
}

RunPlan plan_run(const Experiment& experiment, const std::vector<Case>& cases, const TechniqueRegistry& registry,
                 const MeasurementSettings& settings) {
    RunPlan plan;
    plan.groups = plan_groups(cases, experiment.scenes);
    plan.case_cost.assign(cases.size(), 0.0);
    for (const Case& c : cases) plan.keys.push_back(case_key(c, experiment.scenes[c.scene_index]));
    for (const PlannedGroup& g : plan.groups) {
        double sum = 0;
        for (size_t k = 0; k < g.cases.size(); ++k) {
            const Case& c = cases[g.cases[k]];
            const Technique* technique = registry.find(c.technique);
            const double cost = technique ? estimated_case_cost(c, *technique, settings, k == 0) : 0.0;
            plan.case_cost[g.cases[k]] = cost;
            sum += cost;
        }
        plan.group_cost.push_back(sum);
    }
    return plan;
}

std::vector<size_t> assign_shards(const std::vector<double>& group_cost, size_t shards) {
    if (shards == 0) throw std::invalid_argument("a plan needs at least one shard");
    std::vector<size_t> order(group_cost.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return group_cost[a] > group_cost[b]; });
    std::vector<double> load(shards, 0.0);
    std::vector<size_t> shard_of(group_cost.size(), 0);
    for (size_t g : order) {
        const size_t lightest = size_t(std::min_element(load.begin(), load.end()) - load.begin());
        shard_of[g] = lightest;
        load[lightest] += group_cost[g];
    }
    return shard_of;
}

std::string ShardSpec::text() const { return fmt::format("{}/{}", index + 1, count); }

ShardSpec parse_shard(const std::string& text, const std::string& flag) {
    const size_t slash = text.find('/');
    const auto number = [&](const std::string& part) {
        if (part.empty() || part.find_first_not_of("0123456789") != std::string::npos || part.size() > 6)
            throw std::invalid_argument(fmt::format("{0} {1}: expected i/N with whole numbers, e.g. {0} 2/4", flag, text));
        return size_t(std::stoul(part));
    };
    if (slash == std::string::npos)
        throw std::invalid_argument(fmt::format("{0} {1}: expected i/N, e.g. {0} 2/4", flag, text));
    const size_t i = number(text.substr(0, slash)), n = number(text.substr(slash + 1));
    if (n < 1 || i < 1 || i > n)
        throw std::invalid_argument(fmt::format("{0} {1}: i must be 1 to N (N at least 1), e.g. {0} 1/{2}", flag, text,
                                                std::max<size_t>(n, 1)));
    return ShardSpec{i - 1, n};
}

}  // namespace canopy
