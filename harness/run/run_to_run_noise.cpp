#include "run/run_to_run_noise.hpp"

#include "run/environment.hpp"
#include "report/json_record_reader.hpp"
#include "run/recorded_path.hpp"
#include "run/stability_bench.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <optional>

namespace canopy {

namespace fs = std::filesystem;

double log_ratio_sigma(const std::vector<double>& ratio_per_run) {
    std::vector<double> logs;
    for (double r : ratio_per_run)
        if (std::isfinite(r) && r > 0) logs.push_back(std::log(r));
    if (logs.size() < 2) return 0;
    double mean = 0;
    for (double l : logs) mean += l;
    mean /= double(logs.size());
    double sum = 0;
    for (double l : logs) sum += (l - mean) * (l - mean);
    return std::sqrt(sum / double(logs.size() - 1));
}

namespace {

struct Measured {
    double sigma = 0;
    std::string file, device;
    size_t runs = 0, cases = 0;
};

// The largest sigma of one stability.json's cases; none when it cannot be read.
std::optional<Measured> read_stability(const fs::path& file) {
    std::ifstream in(file);
    nlohmann::json j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (j.is_discarded() || !j.contains("cases") || !j.contains("environment")) return std::nullopt;
    Measured m;
    m.file = recorded_path(file);
    m.device = j["environment"].value("device", std::string());
    if (j.contains("runs") && j["runs"].is_array()) m.runs = j["runs"].size();
    for (const nlohmann::json& c : j["cases"]) {
        if (!c.contains("ratio_per_run") || c.value("group_baseline", false)) continue;
        m.sigma = std::max(m.sigma, log_ratio_sigma(c["ratio_per_run"].get<std::vector<double>>()));
        ++m.cases;
    }
    if (m.cases == 0) return std::nullopt;
    return m;
}

}  // namespace

RunToRunNoise run_to_run_noise(const std::vector<fs::path>& folders, const std::string& device) {
    std::optional<Measured> same_device, any_device;
    for (const fs::path& folder : folders) {
        std::error_code ec;
        if (!fs::is_directory(folder, ec)) continue;
        for (auto it = fs::recursive_directory_iterator(folder, ec); !ec && it != fs::recursive_directory_iterator();
             it.increment(ec)) {
            if (it->path().filename() != "stability.json") continue;
            const std::optional<Measured> m = read_stability(it->path());
            if (!m) continue;
            if (m->device == device && (!same_device || m->sigma > same_device->sigma)) same_device = m;
            if (!any_device || m->sigma > any_device->sigma) any_device = m;
        }
    }
    const std::optional<Measured>& chosen = same_device ? same_device : any_device;
    if (!chosen) return {};
    return {chosen->sigma, fmt::format("{} ({}{}, {} runs, the largest of {} cases)", chosen->file, chosen->device,
                                       same_device ? "" : ": no stability run on this device, the largest elsewhere",
                                       chosen->runs, chosen->cases)};
}

std::vector<fs::path> stability_folders(const fs::path& checkout) {
    std::vector<fs::path> folders{checkout / "results" / "stability"};
    std::error_code ec;
    if (fs::is_directory(checkout / "results" / "gpu", ec))
        for (const fs::directory_entry& device : fs::directory_iterator(checkout / "results" / "gpu", ec))
            if (device.is_directory()) folders.push_back(device.path() / "stability");
    return folders;
}

RunToRunNoise checkout_run_to_run_noise(const std::string& device) {
    return run_to_run_noise(stability_folders(run_checkout()), device);
}

fs::path repeated_run_folder(const fs::path& run_dir, int k) { return run_dir / "runs" / fmt::format("run-{}", k); }

RunToRunNoise run_to_run_noise_for(const RunRecord& run, const fs::path& run_dir) {
    std::vector<RunRecord> runs{run};
    std::error_code ec;
    for (int k = 2; fs::is_regular_file(repeated_run_folder(run_dir, k) / "results.json", ec); ++k) {
        try {
            RunRecord other = read_json_report(repeated_run_folder(run_dir, k) / "results.json");
            if (other.status != "complete" || other.experiment != run.experiment ||
                other.environment.config_hash != run.environment.config_hash ||
                other.environment.device.name != run.environment.device.name ||
                other.environment.git_commit != run.environment.git_commit)
                continue;
            runs.push_back(std::move(other));
        } catch (const std::exception&) {
            continue;  // a half-written or foreign record: not one of the runs
        }
    }
    if (runs.size() < size_t(kMinRunsForOwnNoise)) return checkout_run_to_run_noise(run.environment.device.name);
    const StabilityResult stability = analyse_stability(runs);
    double sigma = 0;
    size_t cases = 0;
    for (const CaseStability& c : stability.cases) {
        if (c.group_baseline || c.ratios.size() < 2) continue;
        sigma = std::max(sigma, log_ratio_sigma(c.ratios));
        ++cases;
    }
    if (cases == 0) return checkout_run_to_run_noise(run.environment.device.name);
    return {sigma, fmt::format("this experiment's {} runs ({}/runs/; the largest of {} cases)", runs.size(),
                               recorded_path(run_dir), cases)};
}

}  // namespace canopy
