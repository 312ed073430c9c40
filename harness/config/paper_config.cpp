#include "config/paper_config.hpp"

#include "config/claim_rules.hpp"
#include "metrics/metric_registry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace canopy {

namespace {

// "better": left is better than right in the metric's direction (metrics/metric_registry.hpp),
// read as "less" or "greater".
const std::vector<std::string> kRelations = {"less", "greater", "about", "better"};

std::string one_of(TomlReader& reader, std::string_view key, const std::string& fallback,
                   const std::vector<std::string>& allowed) {
    const std::string value = reader.get_string(key, fallback);
    if (std::find(allowed.begin(), allowed.end(), value) == allowed.end()) {
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
        const std::string near = closest_match(value, allowed);
        throw reader.error(key, fmt::format("'{}' is not a valid {}", value, reader.describe_key(key)),
                           (near.empty() ? "" : fmt::format("did you mean '{}'? ", near)) + "use one of: " + list);
    }
    return value;
}

PaperRow read_row(TomlReader& r, const TechniqueRegistry& registry, size_t columns) {
    PaperRow row;
    row.where = r.where();
    row.label = r.require_string("label", "label = \"Chebyshev\"");
    row.technique = r.require_string("technique", "technique = \"shadow.vsm\"");
    if (!registry.find(row.technique)) {
        const std::string near = closest_match(row.technique, registry.names());
        throw r.error("technique", fmt::format("unknown technique '{}'", row.technique),
                      (near.empty() ? "" : fmt::format("did you mean '{}'? ", near)) + "run `canopy list`");
    }
    if (auto params = r.get_table("params", "params of paper row '" + row.label + "'")) {
        for (auto&& [key, value] : params->table()) {
            if (!is_param_scalar(value))
                throw params->error_at(value, fmt::format("parameter '{}' must be one value", key.str()), "e.g. precision = \"fp16\"");
            row.params[std::string(key.str())] = to_param_value(value);
            params->node(key.str());
        }
        params->finish();
    }
    if (const toml::node* pass = r.node("pass"); pass && pass->is_array()) {
        row.passes = r.get_string_array("pass");
        if (row.passes.empty())
            throw r.error_at(*pass, "'pass' lists no pass", "pass = \"blades\", or pass = [\"volume_volumes\", \"volume2_volumes\"]");
    } else if (std::string name = r.get_string("pass", ""); !name.empty()) {
        row.passes = {std::move(name)};
    }
    if (const toml::node* values = r.node("values")) {
        const toml::array* array = values->as_array();
        if (!array) throw r.error_at(*values, "'values' must be a list of numbers", "values = [481, 342, 142]");
        for (const toml::node& v : *array) {
            if (v.is_integer()) row.values.push_back(double(v.as_integer()->get()));
            else if (v.is_floating_point()) row.values.push_back(v.as_floating_point()->get());
            else throw r.error_at(v, "'values' must hold numbers (nan for a missing one)", "values = [481, 342, nan]");
        }
    }
    if (!row.values.empty() && row.values.size() != columns)
        throw r.error("values", fmt::format("paper row '{}' has {} values for {} columns", row.label, row.values.size(), columns),
                      "give one number per column, nan where the paper has none");
    r.finish();
    return row;
}

// The paper's left/right time in one column pair from its table, NaN where a row has no number.
double table_ratio(const PaperComparison& paper, const PaperRow& left, const PaperRow& right, size_t left_col,
                   size_t right_col) {
    if (left.values.empty() || right.values.empty()) return std::numeric_limits<double>::quiet_NaN();
    const double a = left.values[left_col], b = right.values[right_col];
    return paper.unit == "fps" ? b / a : a / b;
}

const PaperRow& row_labelled(const PaperComparison& paper, const std::string& label) {
    return *std::find_if(paper.rows.begin(), paper.rows.end(), [&](const PaperRow& r) { return r.label == label; });
}

std::string reason_list() {
    std::string list;
    for (const DirectionReason& reason : direction_reasons())
        list += fmt::format("{}\"{}\" ({})", list.empty() ? "" : ", ", reason.key, reason.meaning);
    return list;
}

// What the claim states of the paper (claim_rules.hpp): its number, checked as a number, or a
// direction with its reason; a claim about what happens in time is tested in time or says why
// not; a tolerance other than the rules' says why.
void read_claim_states(TomlReader& r, const PaperComparison& paper, PaperClaim& claim) {
    const bool timing = claim.metric == kTimeClaim;
    if (!r.has("states"))
        throw r.error("states", "a claim must say whether it checks the paper's number or only a direction",
                      "states = \"magnitude\" (the paper's ratio from its table, or ratio = ...), or states = "
                      "\"direction\" with why = one of: " + reason_list());
    claim.states = one_of(r, "states", "direction", {"magnitude", "direction"}) == "magnitude" ? ClaimStates::magnitude
                                                                                                 : ClaimStates::direction;
    const PaperRow& left = row_labelled(paper, claim.left);
    const PaperRow& right = row_labelled(paper, claim.right);
    bool table_has_ratio = timing;
    std::string table_example;
    for (const auto& [l, rc] : judged_columns(paper, claim)) {
        const double ratio = table_ratio(paper, left, right, l, rc);
        table_has_ratio = table_has_ratio && std::isfinite(ratio) && ratio > 0;
        if (table_example.empty() && std::isfinite(ratio))
            table_example = fmt::format("{:.3g} in column {}", ratio, paper.columns[l]);
    }
    if (claim.states == ClaimStates::direction) {
        claim.why = r.get_string("why", "");
        if (claim.why.empty())
            throw r.error("why", "a claim that checks only a direction must say why", "why = one of: " + reason_list());
        if (!find_direction_reason(claim.why)) {
            std::vector<std::string> keys;
            for (const DirectionReason& reason : direction_reasons()) keys.emplace_back(reason.key);
            const std::string near = closest_match(claim.why, keys);
            throw r.error("why", fmt::format("'{}' is not one of the reasons a claim may check only a direction", claim.why),
                          (near.empty() ? "" : fmt::format("did you mean '{}'? ", near)) + "use one of: " + reason_list());
        }
        if (table_has_ratio)
            throw r.error("states", fmt::format("the paper's table gives this claim's number (left/right = {}): a "
                                                "direction check would not test it",
                                                table_example),
                          "states = \"magnitude\" (the target is taken from the table, column by column)");
        if (const auto number = quoted_measurement(claim.text))
            throw r.error("states", fmt::format("the claim's text quotes '{}', which a direction check does not test", *number),
                          "check it as a number (states = \"magnitude\", with ratio = the paper's left/right where its "
                          "table has none), or leave the number out of the text (paper.md prints canopy's)");
        if (r.has("ratio")) throw r.error("ratio", "'ratio' is the paper's number: it goes with states = \"magnitude\"", "remove ratio");
        if (r.has("ratio_tolerance"))
            throw r.error("ratio_tolerance", "'ratio_tolerance' goes with states = \"magnitude\"", "remove ratio_tolerance");
    } else {
        if (r.has("why")) throw r.error("why", "'why' says why a claim checks only a direction", "remove why, or states = \"direction\"");
        if (r.has("ratio")) {
            claim.ratio = r.get_float("ratio", 0.0);
            if (!(claim.ratio > 0)) throw r.error("ratio", "'ratio' must be positive: the paper's left/right", "ratio = 0.155");
            if (table_has_ratio)
                throw r.error("ratio", fmt::format("the paper's table gives this ratio ({}): it is taken from there", table_example),
                              "remove ratio");
        } else if (!table_has_ratio) {
            throw r.error("ratio",
                          timing ? "the paper's table has no number for one of the rows in a column this claim judges: "
                                   "give the paper's ratio"
                                 : "the paper's table holds times: an error claim's magnitude needs the paper's ratio",
                          "ratio = 0.155 (left/right, as the paper states it), or states = \"direction\" with why");
        }
        const double rule = default_tolerance(timing ? ToleranceUse::time_magnitude : ToleranceUse::error_magnitude);
        claim.ratio_tolerance = r.get_float("ratio_tolerance", rule);
        if (!(claim.ratio_tolerance > 0 && claim.ratio_tolerance < 1))
            throw r.error("ratio_tolerance", "'ratio_tolerance' must lie in (0, 1)", "ratio_tolerance = 0.25");
    }
    claim.tolerance_reason = r.get_string("tolerance_reason", "");
    const bool about_differs = claim.relation == "about" &&
                               claim.tolerance != default_tolerance(timing ? ToleranceUse::time_about : ToleranceUse::error_about);
    const bool magnitude_differs =
        claim.states == ClaimStates::magnitude &&
        claim.ratio_tolerance != default_tolerance(timing ? ToleranceUse::time_magnitude : ToleranceUse::error_magnitude);
    if ((about_differs || magnitude_differs) && claim.tolerance_reason.empty())
        throw r.error(about_differs ? "tolerance" : "ratio_tolerance",
                      "a tolerance other than the rules' table (configs/README.md, \"Claims\") must say why, before the run",
                      "tolerance_reason = \"...\", or remove the tolerance to take the table's");
    if (!about_differs && !magnitude_differs && !claim.tolerance_reason.empty())
        throw r.error("tolerance_reason", "'tolerance_reason' explains a tolerance other than the rules', and none differs",
                      "remove tolerance_reason");
    claim.untested = r.get_string("untested", "");
    if (claim.untested.empty() && claim.metric != "popping")
        if (const auto event = quoted_event_in_time(claim.text))
            throw r.error("text",
                          fmt::format("the claim speaks of '{}', which happens from frame to frame: a still image cannot "
                                      "test it",
                                      *event),
                          "measure it along a [camera_path] (metric = \"popping\"), or say why canopy does not: untested = \"...\"");
}

}  // namespace

PaperComparison read_paper(TomlReader& section, const TechniqueRegistry& registry) {
    PaperComparison paper;
    paper.id = section.require_string("id", "id = \"G-T7.1\"");
    paper.title = section.get_string("title", paper.id);
    paper.source = section.get_string("source", "");
    paper.unit = one_of(section, "unit", "fps", {"fps", "ms"});
    paper.column_key = section.get_string("column_key", "screen");
    paper.columns = section.get_string_array("columns");
    if (paper.columns.empty())
        throw section.error("columns", "[paper] needs its column labels", "columns = [\"512\", \"1024\", \"2048\"]");
    paper.baseline = section.get_string("baseline", "");
    paper.notes = section.get_string("notes", "");
    if (section.has("reference_convergence_flip")) {
        paper.reference_convergence_flip = section.get_float("reference_convergence_flip", 0.0);
        if (paper.reference_convergence_flip < 0)
            throw section.error("reference_convergence_flip", "'reference_convergence_flip' must not be negative",
                                "reference_convergence_flip = 0.052 (scripts/reference-convergence's FLIP(ref N, ref 4N))");
        paper.reference_convergence_source = section.get_string("reference_convergence_source", "");
        if (paper.reference_convergence_source.empty())
            throw section.error("reference_convergence_source", "say where the reference's convergence was measured",
                                "reference_convergence_source = \"results/reference-convergence, 4 samples a pixel\"");
    }
    for (TomlReader& r : section.get_tables("row", "[[paper.row]]")) paper.rows.push_back(read_row(r, registry, paper.columns.size()));
    if (paper.rows.empty()) throw section.error("row", "[paper] has no [[paper.row]] entries", "add one per row of the paper's table");

    auto has_row = [&](const std::string& label) {
        return std::any_of(paper.rows.begin(), paper.rows.end(), [&](const PaperRow& r) { return r.label == label; });
    };
    std::vector<std::string> labels;
    for (const auto& r : paper.rows) labels.push_back(r.label);
    auto check_row = [&](TomlReader& r, std::string_view key, const std::string& label) {
        if (!has_row(label)) {
            const std::string near = closest_match(label, labels);
            throw r.error(key, fmt::format("no paper row is labelled '{}'", label),
                          near.empty() ? "use a row label" : fmt::format("did you mean '{}'?", near));
        }
    };
    if (!paper.baseline.empty()) check_row(section, "baseline", paper.baseline);

    for (TomlReader& r : section.get_tables("claim", "[[paper.claim]]")) {
        PaperClaim claim;
        claim.where = r.where();
        claim.text = r.require_string("text", "text = \"Gaussian CDF costs the same as VSM\"");
        claim.left = r.require_string("left", "left = \"Gaussian CDF\"");
        claim.right = r.require_string("right", "right = \"Chebyshev\"");
        check_row(r, "left", claim.left);
        check_row(r, "right", claim.right);
        claim.metric = one_of(r, "metric", std::string(kTimeClaim), claim_metric_names());
        claim.relation = one_of(r, "relation", "less", kRelations);
        if (claim.relation == "better") claim.relation = claim_metric_better(claim.metric) == Better::lower ? "less" : "greater";
        const bool timing = claim.metric == kTimeClaim;
        const double about_rule = default_tolerance(timing ? ToleranceUse::time_about : ToleranceUse::error_about);
        claim.tolerance = r.get_float("tolerance", about_rule);
        if (claim.tolerance < 0) throw r.error("tolerance", "'tolerance' must not be negative", "tolerance = 0.15");
        if (r.has("tolerance") && claim.relation != "about")
            throw r.error("tolerance", "'tolerance' goes with relation = \"about\"",
                          "the magnitude's tolerance is ratio_tolerance; less and greater take factor or offset");
        claim.factor = r.get_float("factor", claim.factor);
        claim.offset = r.get_float("offset", claim.offset);
        if (!(claim.factor > 0)) throw r.error("factor", "'factor' must be positive", "factor = 0.25");
        if ((claim.factor != 1.0 || claim.offset != 0.0) && claim.relation == "about")
            throw r.error(claim.factor != 1.0 ? "factor" : "offset", "'factor' and 'offset' go with less or greater",
                          "relation = \"less\"");
        if (claim.offset != 0.0 && claim.metric == kTimeClaim)
            throw r.error("offset", "a time claim compares ratios: 'offset' applies to error metrics",
                          "factor = 0.25 (left below a quarter of right)");
        claim.column = r.get_string("column", "");
        const auto check_column = [&](std::string_view key, const std::string& column) {
            if (!column.empty() && std::find(paper.columns.begin(), paper.columns.end(), column) == paper.columns.end()) {
                const std::string near = closest_match(column, paper.columns);
                throw r.error(key, fmt::format("'{}' is not one of the paper's columns", column),
                              near.empty() ? "use a label from columns" : fmt::format("did you mean '{}'?", near));
            }
        };
        check_column("column", claim.column);
        claim.left_column = r.get_string("left_column", "");
        claim.right_column = r.get_string("right_column", "");
        check_column("left_column", claim.left_column);
        check_column("right_column", claim.right_column);
        if (claim.left_column.empty() != claim.right_column.empty())
            throw r.error(claim.left_column.empty() ? "right_column" : "left_column",
                          "a claim across columns needs both left_column and right_column",
                          "left_column = \"high\"\nright_column = \"ant\"");
        if (!claim.left_column.empty() && !claim.column.empty())
            throw r.error("column", "a claim across columns takes left_column and right_column, not column",
                          "remove column");
        read_claim_states(r, paper, claim);
        r.finish();
        paper.claims.push_back(std::move(claim));
    }
    section.finish();
    return paper;
}

}  // namespace canopy
