// What an experiment reproduces from a paper: the paper's table (rows x columns, its numbers),
// the row that normalises times, and claims to check — so a run can print the paper's numbers
// and canopy's side by side with a verdict per claim (report/paper_report.hpp).
#pragma once

#include "core/param.hpp"
#include "scene/scene.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace canopy {

// A case belongs to a row when its technique and every listed parameter match; to a column when
// its `column_key` value equals the column's label ("screen" = "WxH", "scene" = scene name,
// otherwise a parameter name).
struct PaperRow {
    std::string label;                         // "Chebyshev"
    std::string technique;                     // "shadow.vsm"
    std::map<std::string, ParamValue> params;  // subset that must match
    std::vector<double> values;                // the paper's numbers, one per column (NaN: none)
    // The row's time is these GPU passes', not the whole frame's: a part of a frame the paper times
    // apart (Lemme's t_g, t_v, t_i); several (`pass = [...]` in TOML) are summed round by round
    // (Lemme's t_v over his three volume levels). Empty: the frame.
    std::vector<std::string> passes;
    SourceLocation where;
};

// The row's passes as reports name them, joined by " + "; "" for the frame.
inline std::string pass_label(const PaperRow& row) {
    std::string label;
    for (const std::string& name : row.passes) label += (label.empty() ? "" : " + ") + name;
    return label;
}

// What a claim states of the paper: its number (checked as a number) or only a direction.
enum class ClaimStates { magnitude, direction };

// "left relation right" on a metric, for every column where both rows have cases; with
// `states = magnitude` also left/right against the paper's own ratio (config/claim_rules.hpp).
struct PaperClaim {
    std::string text;        // the paper's claim in words
    std::string left, right; // row labels
    // "time" (GPU median ms) or a registered metric's claim name (metrics/metric_registry.hpp,
    // `canopy metrics`).
    std::string metric = "time";
    std::string relation = "less";  // less | greater | about ("better" in the config is read as less or greater)
    double tolerance = 0.15; // about: |left/right - 1| <= tolerance (the rules' table, or tolerance_reason)
    // less and greater compare left with factor x right + offset (e.g. "costs at most a quarter":
    // factor 0.25; "FLIP at most 0.02 above": offset 0.02, error metrics only).
    double factor = 1.0, offset = 0.0;
    std::string column;      // only this column ("" = every column)
    // Left measured in one column and right in another (e.g. two views of a scene, which are
    // measured apart: the ratio is not paired); both or neither.
    std::string left_column, right_column;

    ClaimStates states = ClaimStates::direction;
    std::string why;         // direction: a key of direction_reasons()
    // magnitude: the paper's left/right, given where its table lacks the rows' values (NaN: taken
    // from the table, column by column), and how far canopy's may lie from it (1 ± t).
    double ratio = std::numeric_limits<double>::quiet_NaN();
    double ratio_tolerance = 0.25;
    std::string tolerance_reason;  // why a tolerance differs from the rules' table ("" = it does not)
    // Why canopy does not test it (a claim about what happens from frame to frame, judged on still
    // images); "" = tested.
    std::string untested;
    SourceLocation where;
};

struct PaperComparison {
    std::string id;           // "G-T7.1"
    std::string title;
    std::string source;       // "Gumbau 2011, Table 7.1, L1928-1935"
    std::string unit = "fps"; // the paper's numbers: fps (time = 1000/fps) or ms
    std::string column_key = "screen";
    std::vector<std::string> columns;
    std::string baseline;     // row label normalising each column
    std::vector<PaperRow> rows;
    std::vector<PaperClaim> claims;
    std::string notes;        // printed under the table
    // FLIP between the experiment's reference and one of 4x its pixel samples on this view, as
    // scripts/reference-convergence measured it, and where (NaN: not measured). A FLIP claim is
    // judged only when its margin is at least 10 times this (the reference converged for it).
    double reference_convergence_flip = std::numeric_limits<double>::quiet_NaN();
    std::string reference_convergence_source;
};

// The column pairs (left's, right's) a claim judges: each column with itself (or its one
// `column`), or the one pair across columns. The parser reads the paper's ratio in these, the
// report judges them.
inline std::vector<std::pair<size_t, size_t>> judged_columns(const PaperComparison& paper, const PaperClaim& claim) {
    const auto index = [&](const std::string& label) {
        return size_t(std::find(paper.columns.begin(), paper.columns.end(), label) - paper.columns.begin());
    };
    std::vector<std::pair<size_t, size_t>> pairs;
    if (!claim.left_column.empty()) pairs.emplace_back(index(claim.left_column), index(claim.right_column));
    else
        for (size_t col = 0; col < paper.columns.size(); ++col)
            if (claim.column.empty() || paper.columns[col] == claim.column) pairs.emplace_back(col, col);
    return pairs;
}

}  // namespace canopy
