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
    using Cells = std::vector<std::string>;
    struct MarkdownHeader {
        std::string text;
        bool right = true;
    };
    // A column bound to one run: the headers it adds and a case's cells, as many as headers.
    // Families work out their names (the run's passes, the metrics shown) once, when bound; the
    // cells refer to the run, which must outlive them.
    template <typename Header>
    struct Bound {
        std::vector<Header> headers;
        std::function<Cells(const CaseResult&)> cells;
    };

    std::string name;  // what it holds, for docs and tests ("gpu_ms_median", family: "passes")
    std::function<Bound<std::string>(const RunRecord&)> csv;          // results.csv
    std::function<Bound<MarkdownHeader>(const RunRecord&)> markdown;  // results.md's table; empty: not shown
};

const std::vector<ResultColumn>& result_columns();

}  // namespace canopy
