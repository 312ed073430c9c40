// The per-case columns of results.csv and of results.md's table, each declared once: its CSV
// header and full-precision cell, and, when results.md shows it, its Markdown header and cell.
// A family (the technique's passes, the registered error metrics) expands to one column per name
// the run holds. Both reporters iterate this list in its order; adding a column is one entry in
// result_columns.cpp plus its test (tests/test_result_columns.cpp).
#pragma once

#include "run/case_result.hpp"

#include <functional>
#include <string>
#include <vector>

namespace canopy {

struct ResultColumn {
    std::string name;  // what it holds, for docs and tests ("gpu_ms_median", family: "passes")
    // results.csv: the headers it adds for `run` and a case's cells, as many as headers.
    std::function<std::vector<std::string>(const RunRecord&)> csv_headers;
    std::function<std::vector<std::string>(const RunRecord&, const CaseResult&)> csv_cells;
    // results.md's table (none: not shown there): headers with their alignment, and cells.
    struct MarkdownHeader {
        std::string text;
        bool right = true;
    };
    std::function<std::vector<MarkdownHeader>(const RunRecord&)> markdown_headers;
    std::function<std::vector<std::string>(const RunRecord&, const CaseResult&)> markdown_cells;
};

const std::vector<ResultColumn>& result_columns();

}  // namespace canopy
