#include "config/paper_config.hpp"

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
        claim.tolerance = r.get_float("tolerance", claim.tolerance);
        if (claim.tolerance < 0) throw r.error("tolerance", "'tolerance' must not be negative", "tolerance = 0.15");
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
        r.finish();
        paper.claims.push_back(std::move(claim));
    }
    section.finish();
    return paper;
}

}  // namespace canopy
