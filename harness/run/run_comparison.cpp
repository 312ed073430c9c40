#include "run/run_comparison.hpp"

#include "metrics/metric_registry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace canopy {

namespace {

// Only finite, equal-or-not: NaN (not applicable) on both sides matches, on one side it does not;
// infinite PSNR (identical images) likewise.
bool within(double baseline, double candidate, double allowed) {
    if (std::isnan(baseline) || std::isnan(candidate)) return std::isnan(baseline) && std::isnan(candidate);
    if (std::isinf(baseline) || std::isinf(candidate)) return baseline == candidate;
    return std::abs(candidate - baseline) <= allowed;
}

const std::string* identity_field(const RunRecord& run, const std::string& name) { return run.identity.find(name); }

std::string field_or(const RunRecord& run, const std::string& name) {
    const std::string* v = identity_field(run, name);
    return v ? *v : std::string("?");
}

std::string case_label(const CaseResult& c) {
    return fmt::format("{} {}x{} {}{}", c.scene, c.resolution.width, c.resolution.height, c.technique,
                       c.params_shown.empty() || c.params_shown == "-" ? "" : " " + c.params_shown);
}

TimeChange compare_time(const CaseResult& b, const CaseResult& c, double threshold) {
    TimeChange t;
    const uint64_t seed = bootstrap_seed("compare/" + b.id);
    if (!b.ok || !c.ok || b.gpu_frame.samples_ms.empty() || c.gpu_frame.samples_ms.empty()) return t;
    if (b.group_baseline || c.group_baseline) {
        // Its ratio is 1 by definition; its absolute time moves with the machine's load.
        t.verdict = TimeVerdict::baseline;
        t.baseline_ratio = t.candidate_ratio = {1.0, {1.0, 1.0}, b.gpu_frame.samples_ms.size()};
        t.change = relative_change_with_ci(b.gpu_frame.samples_ms, c.gpu_frame.samples_ms, seed);
        return t;
    }
    if (!b.ratio.measured() || !c.ratio.measured()) return t;
    t.baseline_ratio = b.ratio.estimate;
    t.candidate_ratio = c.ratio.estimate;
    if (std::min(b.ratio.per_round.size(), c.ratio.per_round.size()) < kMinComparedRounds) {
        t.verdict = TimeVerdict::too_few_rounds;
        return t;
    }
    t.change = relative_change_with_ci(b.ratio.per_round, c.ratio.per_round, seed);
    if (t.change.ci.low > threshold) t.verdict = TimeVerdict::regression;
    else if (t.change.ci.high < -threshold) t.verdict = TimeVerdict::improvement;
    else if (t.change.ci.low >= -threshold && t.change.ci.high <= threshold) t.verdict = TimeVerdict::unchanged;
    else t.verdict = TimeVerdict::inconclusive;
    return t;
}

std::vector<MetricChange> compare_errors(const ImageMetrics& b, const ImageMetrics& c) {
    std::vector<MetricChange> changes;
    for (const MetricInfo& m : registered_metrics()) {
        MetricChange change;
        change.metric = m.name;
        change.baseline = b.*m.value;
        change.candidate = c.*m.value;
        change.allowed = m.tolerance.absolute +
                         m.tolerance.relative * (std::isfinite(change.baseline) ? std::abs(change.baseline) : 0.0);
        change.out_of_tolerance = !within(change.baseline, change.candidate, change.allowed);
        changes.push_back(change);
    }
    return changes;
}

}  // namespace

const char* to_string(TimeVerdict verdict) {
    switch (verdict) {
        case TimeVerdict::unchanged: return "unchanged";
        case TimeVerdict::inconclusive: return "inconclusive";
        case TimeVerdict::regression: return "REGRESSION";
        case TimeVerdict::improvement: return "improvement";
        case TimeVerdict::baseline: return "group baseline";
        case TimeVerdict::too_few_rounds: return "too few rounds";
        case TimeVerdict::not_compared: return "not compared";
    }
    return "?";
}

bool CaseComparison::errors_out_of_tolerance() const {
    return std::any_of(errors.begin(), errors.end(), [](const MetricChange& m) { return m.out_of_tolerance; });
}

size_t RunComparison::regressions() const {
    return size_t(std::count_if(cases.begin(), cases.end(),
                                [](const CaseComparison& c) { return c.time.verdict == TimeVerdict::regression; }));
}

size_t RunComparison::improvements() const {
    return size_t(std::count_if(cases.begin(), cases.end(),
                                [](const CaseComparison& c) { return c.time.verdict == TimeVerdict::improvement; }));
}

size_t RunComparison::errors_out_of_tolerance() const {
    return size_t(std::count_if(cases.begin(), cases.end(), [](const CaseComparison& c) { return c.errors_out_of_tolerance(); }));
}

size_t RunComparison::newly_failed() const {
    return size_t(std::count_if(cases.begin(), cases.end(),
                                [](const CaseComparison& c) { return c.failed_candidate && !c.failed_baseline; }));
}

bool RunComparison::passed() const { return regressions() == 0 && errors_out_of_tolerance() == 0 && newly_failed() == 0; }

RunComparison compare_runs(const RunRecord& baseline, const RunRecord& candidate, const ComparisonSettings& settings) {
    if (baseline.experiment != candidate.experiment)
        throw ComparisonRefused(fmt::format("the runs are of different experiments: '{}' and '{}'; compare two runs of "
                                            "one experiment",
                                            baseline.experiment, candidate.experiment));
    if (field_or(baseline, "config_hash") != field_or(candidate, "config_hash"))
        throw ComparisonRefused(fmt::format(
            "the runs of '{}' have different configs (config hash {} and {}: the experiment, a scene or a mesh "
            "changed); compare runs of the same config",
            baseline.experiment, field_or(baseline, "config_hash"), field_or(candidate, "config_hash")));

    RunComparison result;
    result.settings = settings;
    for (const auto& [name, value] : candidate.identity.fields) {
        const std::string before = field_or(baseline, name);
        if (before != value) result.differences.push_back(fmt::format("{}: {} -> {}", name, before, value));
    }

    std::map<std::string, const CaseResult*> candidates;
    for (const CaseResult& c : candidate.cases) candidates.emplace(c.id, &c);
    std::map<std::string, const CaseResult*> baselines;
    for (const CaseResult& b : baseline.cases) baselines.emplace(b.id, &b);
    for (const CaseResult& b : baseline.cases) {
        const auto found = candidates.find(b.id);
        if (found == candidates.end()) {
            result.only_in_baseline.push_back(b.id);
            continue;
        }
        const CaseResult& c = *found->second;
        CaseComparison cc;
        cc.id = b.id;
        cc.label = case_label(c.params_shown.empty() ? b : c);
        cc.failed_baseline = !b.ok;
        cc.failed_candidate = !c.ok;
        if (settings.time) cc.time = compare_time(b, c, settings.threshold);
        if (settings.errors && b.image_error && c.image_error) cc.errors = compare_errors(*b.image_error, *c.image_error);
        result.cases.push_back(std::move(cc));
    }
    for (const CaseResult& c : candidate.cases)
        if (!baselines.count(c.id)) result.only_in_candidate.push_back(c.id);
    return result;
}

}  // namespace canopy
