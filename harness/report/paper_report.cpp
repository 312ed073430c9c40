#include "report/paper_report.hpp"

#include "metrics/reference_degeneracy.hpp"

#include "config/claim_rules.hpp"
#include "core/registry.hpp"
#include "metrics/metric_registry.hpp"
#include "reference/reference_noise.hpp"
#include "report/atomic_file.hpp"
#include "report/text_table.hpp"
#include "run/case_ratio.hpp"
#include "run/statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <cmath>
#include <limits>
#include <optional>

namespace canopy {

namespace {

constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

std::string column_value(const PaperComparison& paper, const CaseResult& c) {
    if (paper.column_key == "screen") return fmt::format("{}x{}", c.resolution.width, c.resolution.height);
    if (paper.column_key == "scene") return c.scene;
    for (const auto& [name, value] : c.params)
        if (name == paper.column_key) return to_string(value);
    return "";
}

bool in_row(const PaperRow& row, const CaseResult& c) {
    if (c.technique != row.technique) return false;
    for (const auto& [name, wanted] : row.params) {
        bool matched = false;
        for (const auto& [have_name, have] : c.params)
            if (have_name == name) matched = to_string(have) == to_string(wanted);
        if (!matched) return false;
    }
    return true;
}

const CaseResult* find_case(const PaperComparison& paper, const RunRecord& run, const PaperRow& row, size_t column) {
    for (const CaseResult& c : run.cases)
        if (c.ok && in_row(row, c) && column_value(paper, c) == paper.columns[column]) return &c;
    return nullptr;
}

// The row's times in case c: the frame's GPU time, or its passes' summed round by round
// (PaperRow::passes); none when the case lacks one of them.
std::optional<TimingSeries> row_series(const PaperRow& row, const CaseResult& c) {
    if (row.passes.empty()) return c.gpu_frame;
    std::vector<const TimingSeries*> parts;
    for (const std::string& name : row.passes) {
        const auto p = std::find_if(c.passes.begin(), c.passes.end(), [&](const TimingSeries& s) { return s.name == name; });
        if (p == c.passes.end() || p->samples_ms.size() != c.passes.front().samples_ms.size()) return std::nullopt;
        parts.push_back(&*p);
    }
    if (parts.size() == 1) return *parts.front();
    TimingSeries sum{.name = pass_label(row), .samples_ms = std::vector<double>(parts.front()->samples_ms.size(), 0.0)};
    for (const TimingSeries* part : parts)
        for (size_t i = 0; i < sum.samples_ms.size(); ++i) sum.samples_ms[i] += part->samples_ms[i];
    sum.stats = summarize(sum.samples_ms);
    return sum;
}

// Row `lr`'s time in case l over row `rr`'s in case r, with its interval.
CaseRatio row_ratio(const PaperRow& lr, const CaseResult& l, const PaperRow& rr, const CaseResult& r) {
    const std::optional<TimingSeries> a = row_series(lr, l), b = row_series(rr, r);
    if (!a || !b) return {Estimate{kMissing, {kMissing, kMissing}, 0}, RatioPairing::unpaired};
    return series_ratio(l, *a, r, *b);
}

const PaperRow* row_named(const PaperComparison& paper, const std::string& label) {
    for (const PaperRow& r : paper.rows)
        if (r.label == label) return &r;
    return nullptr;
}

double paper_time(const PaperComparison& paper, const PaperRow& row, size_t column) {
    if (row.values.empty()) return kMissing;
    const double v = row.values[column];
    return paper.unit == "fps" ? 1000.0 / v : v;
}

// "time" (the row's GPU median: the frame's or its pass's) or a registered metric's claim name;
// NaN where the technique does not declare the metric's group meaningful (ErrorColumns): such a
// column judges nothing.
double metric_of(const PaperRow& row, const CaseResult& c, std::string_view claim) {
    if (claim == kTimeClaim) {
        const std::optional<TimingSeries> series = row_series(row, c);
        return series ? series->stats.median : kMissing;
    }
    const MetricInfo* metric = find_claim_metric(claim);
    if (!metric || !c.image_error) return kMissing;
    return metric->meaningful_value(*c.image_error);
}

// "PSNR (dB; whole image; higher is better)"
// Over which pixels: the metric's group, or its distance band's limits.
std::string table_title(const MetricInfo& metric, const std::optional<DistanceBands>& bands) {
    std::string pixels(group_info(metric.group).description);
    if (metric.band != DistanceBand::none && !bands) pixels = "one distance band's pixels";
    if (metric.band != DistanceBand::none && bands)
        pixels = metric.band == DistanceBand::near     ? fmt::format("pixels whose surface lies under {} from the eye", bands->middle_from)
                 : metric.band == DistanceBand::middle ? fmt::format("pixels whose surface lies {} to {} from the eye",
                                                                     bands->middle_from, bands->far_from)
                                                       : fmt::format("pixels whose surface lies {} or more from the eye", bands->far_from);
    return fmt::format("{} ({}{}; {} is better)", metric.title, metric.unit.empty() ? "" : fmt::format("{}; ", metric.unit),
                       pixels, to_string(metric.better));
}

std::string number(double v, const char* spec = "{:.3g}") {
    if (std::isnan(v)) return "-";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    return fmt::format(fmt::runtime(spec), v);
}

std::string table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
    std::string out = "|";
    for (const auto& h : header) out += " " + h + " |";
    out += "\n|";
    for (size_t i = 0; i < header.size(); ++i) out += i == 0 ? "---|" : "---:|";
    out += "\n";
    for (const auto& row : rows) {
        out += "|";
        for (const auto& cell : row) out += " " + cell + " |";
        out += "\n";
    }
    return out;
}

}  // namespace

Estimate with_run_to_run_noise(const Estimate& e, double sigma) {
    if (!(sigma > 0) || !(e.value > 0) || !(e.ci.low > 0) || !(e.ci.high > 0)) return e;
    // On the log-ratio, each side of the run's own interval and 1.96 sigma added in quadrature:
    // ±1.96 √(se_within² + σ_run²) where the run's interval is symmetric, its shape kept where not.
    const double centre = std::log(e.value), spread = 1.96 * sigma;
    const double below = std::hypot(centre - std::log(e.ci.low), spread);
    const double above = std::hypot(std::log(e.ci.high) - centre, spread);
    Estimate wide = e;
    wide.ci = {std::exp(centre - below), std::exp(centre + above)};
    return wide;
}

namespace {

// "holds" / "does not hold" / "within noise" of an interval against [low, high] (an inside claim)
// or against one boundary (a side claim).
struct Tally {
    int measured = 0, holding = 0, failing = 0;
    void add(bool holds, bool fails) {
        ++measured;
        holding += holds ? 1 : 0;
        failing += fails ? 1 : 0;
    }
    std::string outcome() const {
        if (measured == 0) return "not measured";
        if (failing > 0) return "does not hold";
        if (holding == measured) return "holds";
        return "within noise";
    }
};

// Where two rows a speed claim compares are drawn differently (two cases), how far apart their
// errors lie on the axes their families judge quality by, beyond each metric's compare tolerance:
// "FLIP 0.21 vs 0.09; coverage lost or gained 71 % vs 0.2 %". "" when they agree.
std::string quality_gap(const CaseResult& l, const CaseResult& r) {
    if (&l == &r || !l.image_error || !r.image_error) return "";
    std::vector<std::string> names;
    for (const CaseResult* c : {&l, &r})
        if (const Technique* technique = TechniqueRegistry::instance().find(c->technique))
            for (const std::string& m : technique->pareto_errors())
                if (std::find(names.begin(), names.end(), m) == names.end()) names.push_back(m);
    // FLIP over the whole image, which every family reports, and the coverage lost or gained where
    // the family declares coverage.
    for (const char* shared : {"flip_mean", "coverage_total_error"})
        if (std::find(names.begin(), names.end(), shared) == names.end()) names.push_back(shared);
    std::string gaps;
    for (const std::string& name : names) {
        const MetricInfo* metric = find_metric(name);
        if (!metric) continue;
        const double a = metric->meaningful_value(*l.image_error), b = metric->meaningful_value(*r.image_error);
        if (!std::isfinite(a) || !std::isfinite(b)) continue;
        if (std::abs(a - b) <= metric->tolerance.absolute + metric->tolerance.relative * std::max(std::abs(a), std::abs(b)))
            continue;
        const auto shown = [&](double v) {
            return metric->percent ? fmt::format("{:.3g} %", 100.0 * v) : fmt::format("{:.3g}", v);
        };
        gaps += fmt::format("{}{} {} vs {}", gaps.empty() ? "" : "; ", metric->column, shown(a), shown(b));
    }
    return gaps;
}

// The spread of a claim's margin over the reference's noisy replicates, left's and right's taken
// replicate by replicate (the same perturbation for both); NaN when either case lacks them.
double reference_noise_of_margin(const std::string& claim_metric, const CaseResult& l, const CaseResult& r,
                                 const std::function<double(double, double)>& margin) {
    const MetricInfo* metric = find_claim_metric(claim_metric);
    if (!metric) return kMissing;
    const auto a = l.reference_replicates.find(std::string(metric->name));
    const auto b = r.reference_replicates.find(std::string(metric->name));
    if (a == l.reference_replicates.end() || b == r.reference_replicates.end() || a->second.size() != b->second.size())
        return kMissing;
    std::vector<double> margins;
    for (size_t k = 0; k < a->second.size(); ++k) margins.push_back(margin(a->second[k], b->second[k]));
    return replicate_spread(margins);
}

std::string direction_reason(const PaperClaim& claim) {
    const DirectionReason* reason = find_direction_reason(claim.why);
    return reason ? std::string(reason->meaning) : claim.why;
}

}  // namespace

std::vector<ClaimVerdict> judge_claims(const PaperComparison& paper, const RunRecord& run, const RunToRunNoise& noise) {
    std::vector<ClaimVerdict> verdicts;
    const bool cpu_rasteriser = run.environment.device.is_lavapipe();
    for (const PaperClaim& claim : paper.claims) {
        ClaimVerdict v;
        v.text = claim.text;
        v.magnitude_stated = claim.states == ClaimStates::magnitude;
        if (!v.magnitude_stated) v.direction_only = direction_reason(claim);
        if (!claim.untested.empty()) {
            v.outcome = "not tested by canopy";
            v.because = claim.untested;
            if (v.magnitude_stated) v.magnitude_outcome = "not tested by canopy";
            verdicts.push_back(v);
            continue;
        }
        const PaperRow* left = row_named(paper, claim.left);
        const PaperRow* right = row_named(paper, claim.right);
        std::string numbers, magnitudes, gaps;
        Tally direction, magnitude;
        bool noise_unknown = false;
        std::string unconverged, flagged;
        size_t fewest_samples = std::numeric_limits<size_t>::max();
        const bool timing = claim.metric == kTimeClaim;
        const double t = claim.ratio_tolerance;
        for (const auto& [col, right_col] : judged_columns(paper, claim)) {
            const CaseResult* l = find_case(paper, run, *left, col);
            const CaseResult* r = find_case(paper, run, *right, right_col);
            if (!l || !r) continue;
            const std::string where = col == right_col ? paper.columns[col]
                                                       : paper.columns[col] + " vs " + paper.columns[right_col];
            // A case measured against a degenerate reference (every technique matches it) decides
            // nothing, its time included: the scene is not the one the claim is about.
            const std::vector<std::string>& left_flags = degenerate_reasons(run, *l);
            if (const auto& reasons = left_flags.empty() ? degenerate_reasons(run, *r) : left_flags; !reasons.empty()) {
                flagged += fmt::format("{}{}: {}", flagged.empty() ? "" : "; ", where, degenerate_reference_text(reasons));
                continue;
            }
            // The paper's left/right in this column pair: the claim's, or its table's.
            const double target = std::isfinite(claim.ratio)
                                      ? claim.ratio
                                      : paper_time(paper, *left, col) / paper_time(paper, *right, right_col);
            if (timing) {
                // left / right with its 95 % interval widened by the run-to-run spread: a claim is
                // decided only when the interval lies wholly on one side.
                const CaseRatio ratio = row_ratio(*left, *l, *right, *r);
                if (std::isnan(ratio.estimate.value)) continue;
                const Estimate e = with_run_to_run_noise(ratio.estimate, noise.sigma);
                fewest_samples = std::min({fewest_samples, row_series(*left, *l)->samples_ms.size(),
                                           row_series(*right, *r)->samples_ms.size()});
                if (claim.relation == "less") direction.add(e.ci.high < claim.factor, e.ci.low > claim.factor);
                else if (claim.relation == "greater") direction.add(e.ci.low > claim.factor, e.ci.high < claim.factor);
                else
                    direction.add(e.ci.low >= 1.0 - claim.tolerance && e.ci.high <= 1.0 + claim.tolerance,
                                  e.ci.low > 1.0 + claim.tolerance || e.ci.high < 1.0 - claim.tolerance);
                numbers += fmt::format("{}{}: {} vs {} ms, ratio {}{}", numbers.empty() ? "" : "; ", where,
                                       number(metric_of(*left, *l, kTimeClaim), "{:.4g}"),
                                       number(metric_of(*right, *r, kTimeClaim), "{:.4g}"), ratio_cell(e),
                                       ratio.pairing == RatioPairing::unpaired ? " (not paired: other groups)" : "");
                if (v.magnitude_stated && std::isfinite(target) && target > 0) {
                    const double k = e.value / target, k_low = e.ci.low / target, k_high = e.ci.high / target;
                    magnitude.add(k_low >= 1.0 - t && k_high <= 1.0 + t, k_low > 1.0 + t || k_high < 1.0 - t);
                    magnitudes += fmt::format("{}{}: ×{} [{}, {}] of the paper's {:.3g}", magnitudes.empty() ? "" : "; ",
                                              where, ratio_number(k), ratio_number(k_low), ratio_number(k_high), target);
                }
                if (const std::string gap = quality_gap(*l, *r); !gap.empty())
                    gaps += fmt::format("{}{}: {}", gaps.empty() ? "" : "; ", where, gap);
            } else {
                const double a = metric_of(*left, *l, claim.metric), b = metric_of(*right, *r, claim.metric);
                if (std::isnan(a) || std::isnan(b)) continue;
                // Renders are deterministic; the reference is not. The margin by which the relation
                // holds (> 0) or fails (< 0), and the same against each of the reference's noisy
                // replicates (reference/reference_noise.hpp): a margin inside 1.96 times their
                // spread decides nothing.
                const auto margin = [&](double left_value, double right_value) {
                    const double bound = claim.factor * right_value + claim.offset;
                    if (claim.relation == "less") return bound - left_value;
                    if (claim.relation == "greater") return left_value - bound;
                    return claim.tolerance * std::abs(right_value) - std::abs(left_value - right_value);
                };
                const double m = margin(a, b);
                const double noise = reference_noise_of_margin(claim.metric, *l, *r, margin);
                noise_unknown = noise_unknown || std::isnan(noise);
                // A FLIP claim on a reference that has not converged for it: FLIP(ref N, ref 4N)
                // above a tenth of the margin decides nothing.
                const bool flip_claim = claim.metric.rfind("flip", 0) == 0;
                if (flip_claim && std::isfinite(paper.reference_convergence_flip) &&
                    std::abs(m) < 10.0 * paper.reference_convergence_flip) {
                    direction.add(false, false);
                    unconverged = fmt::format("; the reference has not converged for this margin: FLIP(ref N, ref 4N) "
                                              "= {:.3g} is more than a tenth of it ({})",
                                              paper.reference_convergence_flip, paper.reference_convergence_source);
                } else if (std::isnan(noise) || noise == 0.0) {
                    // Exact: "about" holds on its boundary, less and greater fail there.
                    if (claim.relation == "about") direction.add(m >= 0, m < 0);
                    else direction.add(m > 0, m <= 0);
                } else {
                    direction.add(m > 1.96 * noise, m < -1.96 * noise);
                }
                numbers += fmt::format("{}{}: {} vs {}{}{}", numbers.empty() ? "" : "; ", where,
                                       number(a, "{:.4g}"), number(b, "{:.4g}"),
                                       claim.relation == "about" && b != 0.0 ? fmt::format(" (ratio {:.2f})", a / b) : "",
                                       std::isnan(noise) ? std::string()
                                                         : fmt::format(", margin {:.3g} against the reference's noise ±{:.2g}",
                                                                       m, 1.96 * noise));
                if (v.magnitude_stated && b != 0.0 && std::isfinite(target)) {
                    const double k = (a / b) / target;
                    magnitude.add(std::abs(k - 1.0) <= t, std::abs(k - 1.0) > t);
                    magnitudes += fmt::format("{}{}: ×{} of the paper's {:.3g}", magnitudes.empty() ? "" : "; ", where,
                                              ratio_number(k), target);
                }
            }
        }
        const bool too_few = direction.measured > 0 && fewest_samples < kMinTimingSamples;
        v.outcome = too_few ? "too few samples" : direction.outcome();
        const std::string relation = claim.relation == "about" ? fmt::format("within {:.0f} % of", 100.0 * claim.tolerance)
                                     : claim.relation == "less" ? "below" : "above";
        const std::string bound = fmt::format("{}{}'s{}", claim.factor != 1.0 ? fmt::format("{:g} x ", claim.factor) : "",
                                              claim.right, claim.offset != 0.0 ? fmt::format(" {:+g}", claim.offset) : "");
        v.because = direction.measured ? fmt::format("{} of {} is {} {}: {}", claim.metric, claim.left, relation, bound, numbers)
                                       : "no measured case for one of the rows";
        if (direction.measured == 0 && !flagged.empty()) {
            v.outcome = "not judged: flagged case";
            v.because = "every case it compares is flagged";
        }
        if (too_few)
            v.because = fmt::format("too few samples ({} < {}) to judge a timing claim; {}", fewest_samples,
                                    kMinTimingSamples, v.because);
        if (v.magnitude_stated) {
            v.magnitude = magnitudes;
            v.magnitude_outcome = too_few ? "too few samples" : magnitude.outcome();
            // A CPU rasteriser is not the paper's class of hardware: its ratios say how the
            // techniques' costs fall there, not whether the paper's numbers reproduce.
            if (timing && cpu_rasteriser && magnitude.measured > 0) v.magnitude_outcome = "not judged on a CPU rasteriser";
            if (magnitude.measured > 0)
                v.magnitude += fmt::format(" (holds inside 1 ± {:g})", t);
        }
        if (!gaps.empty()) v.unequal_quality = "unequal quality: " + gaps;
        v.because += unconverged;
        if (!flagged.empty()) v.because += "; not judged where the case is flagged (" + flagged + ")";
        if (noise_unknown && direction.measured > 0)
            v.because += "; the reference's noise was not measured by this run (made before canopy measured it): "
                         "the verdict does not account for it";
        verdicts.push_back(v);
    }
    return verdicts;
}

std::string paper_report(const PaperComparison& paper, const RunRecord& run, const RunToRunNoise& noise) {
    std::string out = fmt::format("# {} — {}\n\n", paper.id, paper.title);
    if (!paper.source.empty()) out += fmt::format("Source: {}.\n\n", paper.source);
    const Environment& e = run.environment;
    out += fmt::format("canopy {} on {} ({}), nproc {}, LP_NUM_THREADS {}, commit {}; experiment `{}` (config hash {}); "
                       "{} warm-up frames + {} rounds of {} frame{} per case{}.\n\n",
                       e.canopy_version, e.device.name, e.device.driver_info, e.nproc, e.lp_num_threads, commit_text(e),
                       run.config_file, e.config_hash,
                       run.warmup_frames, run.rounds, run.frames_per_sample, run.frames_per_sample == 1 ? "" : "s",
                       run.quick ? " (--quick)" : "");
    // A reference every technique matches: its cases' numbers below say nothing about the techniques.
    for (const ReferenceRecord& r : run.references)
        if (!r.degenerate.empty())
            out += fmt::format("**Flagged:** {} {}x{}: {}. Every technique scores near perfect against it: its cases' "
                               "errors say nothing about them, and no claim's verdict rests on them.\n\n",
                               r.scene, r.resolution.width, r.resolution.height, degenerate_reference_text(r.degenerate));

    const PaperRow* base = paper.baseline.empty() ? nullptr : row_named(paper, paper.baseline);
    std::vector<std::string> header{"row"};
    for (const auto& c : paper.columns) header.push_back(c);

    // Time relative to the baseline row: paper -> canopy.
    if (base) {
        std::vector<std::vector<std::string>> rows;
        for (const PaperRow& row : paper.rows) {
            std::vector<std::string> cells{row.label};
            for (size_t col = 0; col < paper.columns.size(); ++col) {
                const double paper_ratio = paper_time(paper, row, col) / paper_time(paper, *base, col);
                const CaseResult* mine = find_case(paper, run, row, col);
                const CaseResult* mine_base = find_case(paper, run, *base, col);
                std::string canopy_ratio = "-";
                if (mine && mine_base) {
                    const Estimate e = with_run_to_run_noise(row_ratio(row, *mine, *base, *mine_base).estimate, noise.sigma);
                    if (!std::isnan(e.value))
                        canopy_ratio = fmt::format("**{}** [{}, {}]", ratio_number(e.value), ratio_number(e.ci.low),
                                                   ratio_number(e.ci.high));
                }
                cells.push_back(fmt::format("{} → {}", std::isnan(paper_ratio) ? "-" : ratio_number(paper_ratio), canopy_ratio));
            }
            rows.push_back(cells);
        }
        out += fmt::format("## Frame time relative to {} (paper → **canopy**)\n\n", paper.baseline);
        out += table(header, rows);
        bool pass_rows = false;
        for (const PaperRow& row : paper.rows) pass_rows = pass_rows || !row.passes.empty();
        out += fmt::format("\nPaper: time = {}; canopy: GPU time of all passes (Vulkan timestamps{}) relative to the "
                           "baseline row, paired sample by sample (cases of one scene and resolution are measured "
                           "together, round by round, each sample between two of the group's baseline), median over "
                           "the rounds, [95 % block-bootstrap interval]. Ratios "
                           "compare, absolute times do not: the paper ran on a 2008-2010 GPU, canopy on {}.\n\n",
                           paper.unit == "fps" ? "1000 / fps" : "ms",
                           pass_rows ? "; a row naming a pass: that pass's, its share of the baseline's frame when the "
                                       "two rows are one case"
                                     : "",
                           e.device.name);
    }

    // Raw numbers.
    std::vector<std::vector<std::string>> raw;
    for (const PaperRow& row : paper.rows) {
        std::vector<std::string> cells{row.label};
        for (size_t col = 0; col < paper.columns.size(); ++col) {
            const CaseResult* mine = find_case(paper, run, row, col);
            const std::string paper_value = row.values.empty() ? "-" : number(row.values[col], "{:.4g}") + " " + paper.unit;
            const std::optional<TimingSeries> series = mine ? row_series(row, *mine) : std::nullopt;
            cells.push_back(fmt::format("{} / {}", paper_value,
                                        series ? fmt::format("{:.2f} ± {:.2f} ms", series->stats.median, series->stats.mad)
                                               : std::string("-")));
        }
        raw.push_back(cells);
    }
    out += "## Raw numbers (paper / canopy median ± MAD)\n\n" + table(header, raw) + "\n";

    // Error against the ray-traced reference.
    const bool errors = !run.references.empty();
    if (errors) {
        for (const MetricInfo& metric : registered_metrics()) {
            if (!metric.shown_in(shown_in_paper_tables)) continue;
            const std::string claim(metric.claim), title = table_title(metric, run.distance_bands);
            std::vector<std::vector<std::string>> rows;
            bool any_value = false;  // a metric no row's technique declares (a shadow metric for grass) is left out
            for (const PaperRow& row : paper.rows) {
                if (!row.passes.empty()) continue;  // a part of a frame: the image's error is its frame row's
                std::vector<std::string> cells{row.label};
                for (size_t col = 0; col < paper.columns.size(); ++col) {
                    const CaseResult* mine = find_case(paper, run, row, col);
                    cells.push_back(mine ? number(metric_of(row, *mine, claim), "{:.4g}") : "-");
                    any_value = any_value || cells.back() != "-";
                }
                rows.push_back(cells);
            }
            if (any_value) out += "## canopy: " + title + "\n\n" + table(header, rows) + "\n";
        }
        // The reference's own classes of pixels per column: how much umbra and penumbra there is
        // (for techniques that declare shadow columns).
        bool shadows = false;
        for (const PaperRow& row : paper.rows)
            for (size_t col = 0; col < paper.columns.size(); ++col)
                if (const CaseResult* mine = find_case(paper, run, row, col); mine && mine->image_error)
                    shadows = shadows || mine->image_error->columns.visibility || mine->image_error->columns.shadow_regions;
        std::vector<std::vector<std::string>> classes;
        for (const MetricCountInfo& count : registered_metric_counts()) {
            if (count.label.empty()) continue;
            std::vector<std::string> cells{std::string(count.label)};
            for (size_t col = 0; col < paper.columns.size(); ++col) {
                const CaseResult* any = nullptr;
                for (const PaperRow& row : paper.rows)
                    if (!any) any = find_case(paper, run, row, col);
                cells.push_back(any && any->image_error ? std::to_string((*any->image_error).*count.value) : "-");
            }
            classes.push_back(cells);
        }
        if (shadows) {
            out += "## Reference: pixels in full umbra, fully lit and in penumbra (0 < V < 1)\n\n" + table(header, classes) + "\n";
            out += "The papers define no error metric: these are canopy's, against an Embree reference with the same "
                   "shading model and the area light integrated. PSNR and FLIP say how far the image is from the truth "
                   "(aliased silhouettes and shading included); the visibility RMSE says how wrong the technique's shadow "
                   "is: the visibility it gave the light against the reference's, at the same pixel centres. The pixel "
                   "classes are the reference's at the pixel centres (1024 light samples), off silhouettes.\n\n";
        } else {
            out += "The papers define no error metric: these are canopy's, against an Embree reference with the same "
                   "shading model. PSNR and FLIP say how far the image is from the truth.\n\n";
        }
    }

    const auto verdicts = judge_claims(paper, run, noise);
    if (!verdicts.empty()) {
        out += "## Claims\n\n";
        bool magnitude_not_judged = false;
        for (const ClaimVerdict& v : verdicts) {
            out += fmt::format("- **{}** — {}\n  - {}\n", v.outcome, v.text, v.because);
            if (v.magnitude_stated)
                out += fmt::format("  - the paper's number: **{}**{}\n", v.magnitude_outcome,
                                   v.magnitude.empty() ? "" : " — " + v.magnitude);
            else
                out += fmt::format("  - a direction only: {}\n", v.direction_only);
            if (!v.unequal_quality.empty()) out += "  - **" + v.unequal_quality + "**\n";
            magnitude_not_judged = magnitude_not_judged || v.magnitude_outcome == "not judged on a CPU rasteriser";
        }
        out += fmt::format("\nA timing claim compares the two rows' time ratio, paired round by round, and holds or "
                           "fails only when its 95 % interval lies wholly on one side (for \"about\": wholly inside "
                           "or outside the tolerance); otherwise the verdict is \"within noise\". The interval is the "
                           "run's own, widened on the log-ratio by the spread between runs (±1.96 √(se_within² + "
                           "σ_run²)), σ_run = {}: a margin smaller than what moves between two runs decides nothing. "
                           "Timings of fewer than {} rounds (--quick measures 3) judge no claim: \"too few samples\". "
                           "Error claims compare deterministic renders against a reference that is not: each margin is also taken against the reference perturbed by its own noise, replicate by replicate, and one inside 1.96 times their spread reads \"within noise\". A claim that states the paper's number "
                           "(\"magnitude\") is also judged as × k of the paper's ratio, within the tolerance of "
                           "configs/README.md's table; one that checks a direction says why. A speed claim whose two "
                           "rows differ in error beyond the metric's compare tolerance says so (\"unequal quality\"). "
                           "A claim about what happens from frame to frame that canopy does not measure along a path "
                           "reads \"not tested by canopy\", with the reason.\n\n",
                           noise.known() ? fmt::format("{:.2g} % ({})", 100.0 * noise.sigma, noise.source)
                                         : std::string("0: not known (no `canopy bench stability` results in this checkout)"),
                           kMinTimingSamples);
        if (magnitude_not_judged)
            out += "The magnitudes of timing claims are given, not judged: this run used a CPU rasteriser, which is "
                   "not the paper's class of hardware (vertex work on one thread, fragments on all cores); a GPU "
                   "run (results/gpu/) judges them.\n\n";
    }
    if (!paper.notes.empty()) out += paper.notes + "\n";
    return out;
}

void write_paper_report(const std::filesystem::path& path, const PaperComparison& paper, const RunRecord& run,
                        const RunToRunNoise& noise) {
    write_text_atomically(path, paper_report(paper, run, noise));
}

namespace {

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace

nlohmann::json paper_data(const PaperComparison& paper, const RunRecord& run, const RunToRunNoise& noise) {
    using nlohmann::json;
    json data{{"id", paper.id},         {"title", paper.title},     {"source", paper.source},
              {"unit", paper.unit},     {"column_key", paper.column_key}, {"columns", paper.columns},
              {"baseline", paper.baseline}, {"experiment", run.experiment}, {"config", run.config_file},
              {"commit", run.environment.git_commit}, {"commit_dirty", run.environment.git_dirty},
              {"device", run.environment.device.name}, {"driver", run.environment.device.driver_info},
              {"quick", run.quick},     {"rounds", run.rounds},
              // The run the numbers come from, as its results.json records it.
              {"environment", run.environment}};
    const PaperRow* base = paper.baseline.empty() ? nullptr : row_named(paper, paper.baseline);
    json rows = json::array();
    for (const PaperRow& row : paper.rows) {
        json r{{"label", row.label}, {"technique", row.technique}, {"pass", pass_label(row)}};
        json params = json::object();
        for (const auto& [name, value] : row.params) params[name] = to_string(value);
        r["params"] = params;
        json values = json::array(), paper_ratio = json::array(), ratio = json::array(), ms = json::array(),
             ids = json::array();
        json errors = json::object();
        for (size_t col = 0; col < paper.columns.size(); ++col) {
            values.push_back(row.values.empty() ? json(nullptr) : number_or_null(row.values[col]));
            paper_ratio.push_back(base ? number_or_null(paper_time(paper, row, col) / paper_time(paper, *base, col)) : json(nullptr));
            const CaseResult* mine = find_case(paper, run, row, col);
            const CaseResult* mine_base = base ? find_case(paper, run, *base, col) : nullptr;
            json canopy_ratio = nullptr;
            if (mine && mine_base) {
                const Estimate e = with_run_to_run_noise(row_ratio(row, *mine, *base, *mine_base).estimate, noise.sigma);
                if (std::isfinite(e.value))
                    canopy_ratio = json{{"median", e.value}, {"low", number_or_null(e.ci.low)}, {"high", number_or_null(e.ci.high)}};
            }
            ratio.push_back(canopy_ratio);
            const std::optional<TimingSeries> series = mine ? row_series(row, *mine) : std::nullopt;
            ms.push_back(series ? json{{"median", series->stats.median}, {"mad", series->stats.mad}} : json(nullptr));
            ids.push_back(mine ? json(mine->id) : json(nullptr));
            for (const MetricInfo& metric : registered_metrics()) {
                json& column_values = errors[std::string(metric.name)];
                if (column_values.is_null()) column_values = json::array();
                const bool frame_row = row.passes.empty();
                column_values.push_back(mine && frame_row && mine->image_error
                                            ? number_or_null(metric.meaningful_value(*mine->image_error))
                                            : json(nullptr));
            }
        }
        r["paper_values"] = values;
        r["paper_ratio"] = paper_ratio;
        r["canopy_ratio"] = ratio;
        r["canopy_ms"] = ms;
        r["case_ids"] = ids;
        r["errors"] = errors;
        rows.push_back(r);
    }
    data["rows"] = rows;
    json claims = json::array();
    const std::vector<ClaimVerdict> verdicts = judge_claims(paper, run, noise);
    for (size_t i = 0; i < verdicts.size(); ++i) {
        json claim{{"text", verdicts[i].text},
                   {"outcome", verdicts[i].outcome},
                   {"because", verdicts[i].because},
                   {"metric", paper.claims[i].metric},
                   {"left", paper.claims[i].left},
                   {"right", paper.claims[i].right},
                   {"states", paper.claims[i].states == ClaimStates::magnitude ? "magnitude" : "direction"},
                   {"unequal_quality", verdicts[i].unequal_quality}};
        if (paper.claims[i].states == ClaimStates::direction) claim["why"] = paper.claims[i].why;
        if (verdicts[i].magnitude_stated)
            claim["magnitude"] = json{{"outcome", verdicts[i].magnitude_outcome}, {"because", verdicts[i].magnitude},
                                      {"tolerance", paper.claims[i].ratio_tolerance}};
        if (!paper.claims[i].untested.empty()) claim["untested"] = paper.claims[i].untested;
        claims.push_back(claim);
    }
    data["claims"] = claims;
    // Every noise source a timing interval holds: the run's own (block bootstrap) and between runs.
    data["run_to_run_noise"] = json{{"sigma_log_ratio", noise.sigma},
                                    {"source", noise.known() ? noise.source : std::string("not known")}};
    return data;
}

void write_paper_data(const std::filesystem::path& path, const PaperComparison& paper, const RunRecord& run,
                      const RunToRunNoise& noise) {
    write_text_atomically(path, paper_data(paper, run, noise).dump(1) + "\n");
}

}  // namespace canopy
