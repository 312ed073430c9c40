#include "report/csv_report.hpp"

#include "report/atomic_file.hpp"
#include "report/result_columns.hpp"

namespace canopy {

std::string csv_report(const RunRecord& run) {
    // Every column from the one list (report/result_columns.hpp), in its order.
    const std::vector<ResultColumn>& columns = result_columns();
    std::string out;
    const auto append = [&out](const std::vector<std::string>& cells) {
        for (const std::string& cell : cells) out += (out.empty() || out.back() == '\n' ? "" : ",") + cell;
    };
    for (const ResultColumn& column : columns) append(column.csv_headers(run));
    out += "\n";
    for (const CaseResult& c : run.cases) {
        for (const ResultColumn& column : columns) append(column.csv_cells(run, c));
        out += "\n";
    }
    return out;
}

void write_csv_report(const std::filesystem::path& path, const RunRecord& run) {
    write_text_atomically(path, csv_report(run));
}

}  // namespace canopy
