#include "report/csv_report.hpp"

#include "report/atomic_file.hpp"
#include "report/result_columns.hpp"

namespace canopy {

std::string csv_report(const RunRecord& run) {
    // Every column from the one list (report/result_columns.hpp), in its order.
    std::vector<ResultColumn::Bound<std::string>> columns;
    for (const ResultColumn& column : result_columns()) columns.push_back(column.csv(run));
    std::string out;
    const auto append = [&out](const std::vector<std::string>& cells) {
        for (const std::string& cell : cells) out += (out.empty() || out.back() == '\n' ? "" : ",") + cell;
    };
    for (const auto& column : columns) append(column.headers);
    out += "\n";
    for (const CaseResult& c : run.cases) {
        for (const auto& column : columns) append(column.cells(c));
        out += "\n";
    }
    return out;
}

void write_csv_report(const std::filesystem::path& path, const RunRecord& run) {
    write_text_atomically(path, csv_report(run));
}

}  // namespace canopy
