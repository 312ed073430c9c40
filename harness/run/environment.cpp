#include "run/environment.hpp"

#include "run/binary_freshness.hpp"

#include "run/heap_settings.hpp"

#include <fmt/chrono.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <sched.h>

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>
#include <unistd.h>

#include <optional>

namespace canopy {

namespace {

std::string command_output(const std::string& command) {
    std::string out;
    if (FILE* pipe = popen(command.c_str(), "r")) {
        char buffer[256];
        while (fgets(buffer, sizeof buffer, pipe)) out += buffer;
        pclose(pipe);
    }
    while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
    return out;
}

std::string cpu_model() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line))
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    return "unknown";
}

double cpu_mhz() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line))
        if (line.rfind("cpu MHz", 0) == 0) return std::atof(line.substr(line.find(':') + 1).c_str());
    return 0.0;
}

std::string first_line(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);
    return line;
}

// "0-3,8" -> 5
int cpu_list_size(const std::string& list) {
    int count = 0;
    std::stringstream ranges(list);
    std::string range;
    while (std::getline(ranges, range, ',')) {
        const size_t dash = range.find('-');
        if (range.empty()) continue;
        count += dash == std::string::npos ? 1 : std::atoi(range.c_str() + dash + 1) - std::atoi(range.c_str()) + 1;
    }
    return count;
}

std::vector<CpuCache> cpu_caches() {
    std::vector<CpuCache> caches;
    const std::filesystem::path dir = "/sys/devices/system/cpu/cpu0/cache";
    for (int index = 0; index < 16; ++index) {
        const std::filesystem::path entry = dir / ("index" + std::to_string(index));
        if (!std::filesystem::exists(entry / "level")) break;
        CpuCache c;
        c.type = first_line(entry / "type");
        c.level = std::atoi(first_line(entry / "level").c_str());
        const std::string size = first_line(entry / "size");  // "48K"
        long long bytes = std::atoll(size.c_str());
        if (size.find('K') != std::string::npos) bytes <<= 10;
        if (size.find('M') != std::string::npos) bytes <<= 20;
        c.size_bytes = bytes;
        c.num_sharing = cpu_list_size(first_line(entry / "shared_cpu_list"));
        caches.push_back(c);
    }
    return caches;
}

std::string cpus_allowed() {
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof set, &set) != 0) return "unknown";
    std::string list;
    for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu) {
        if (!CPU_ISSET(cpu, &set)) continue;
        int last = cpu;
        while (last + 1 < CPU_SETSIZE && CPU_ISSET(last + 1, &set)) ++last;
        list += (list.empty() ? "" : ",") + (last == cpu ? std::to_string(cpu) : fmt::format("{}-{}", cpu, last));
        cpu = last;
    }
    return list;
}

// GIT_OPTIONAL_LOCKS=0: reading the checkout's state takes no lock (`git status` would otherwise
// refresh the index under .git/index.lock, colliding with the user's own git commands). A path
// with a quote is never put in the shell command.
std::string git_command(const std::filesystem::path& checkout) {
    const std::string dir = checkout.string();
    if (dir.find('\'') != std::string::npos) return "false ";
    return "GIT_OPTIONAL_LOCKS=0 git -C '" + dir + "' ";
}

std::string git_head(const std::filesystem::path& checkout) {
    return command_output(git_command(checkout) + "rev-parse HEAD 2>/dev/null");
}

// The files with uncommitted changes, results/ left out: regenerating committed results rewrites
// tracked files there, which says nothing about the code.
std::vector<std::string> changed_files(const std::filesystem::path& checkout) {
    std::vector<std::string> files;
    std::istringstream lines(command_output(git_command(checkout) +
                                            "status --porcelain --untracked-files=no -- . ':(exclude)results' 2>/dev/null"));
    for (std::string line; std::getline(lines, line);)
        if (line.size() > 3) files.push_back(line.substr(3));
    return files;
}

std::filesystem::path& chosen_run_checkout() {
    static std::filesystem::path checkout;
    return checkout;
}

// A bundle (scripts/gpu-bundle) is configured with the commit it is built from: that, not the git
// state of the copy it runs in (stale or absent on the machine it travels to), says which code ran.
bool built_from_recorded_commit() { return *CANOPY_BUILD_COMMIT != '\0'; }

}  // namespace

std::string canopy_build_type() { return CANOPY_BUILD_TYPE; }

std::filesystem::path source_checkout() { return CANOPY_SOURCE_DIR; }

std::filesystem::path checkout_of(const std::filesystem::path& path) {
    namespace fs = std::filesystem;
    std::error_code error;
    fs::path dir = fs::weakly_canonical(fs::absolute(path, error), error);
    if (error) return {};
    if (!fs::is_directory(dir, error)) dir = dir.parent_path();
    for (; !dir.empty(); dir = dir.parent_path()) {
        if (fs::exists(dir / ".git", error)) return dir;
        if (dir == dir.root_path()) break;
    }
    return {};
}

std::filesystem::path run_checkout() {
    if (!chosen_run_checkout().empty()) return chosen_run_checkout();
    std::error_code error;
    const std::filesystem::path here = checkout_of(std::filesystem::current_path(error));
    return here.empty() ? source_checkout() : here;
}

void set_run_checkout_of(const std::filesystem::path& path) {
    const std::filesystem::path checkout = checkout_of(path);
    if (!checkout.empty()) chosen_run_checkout() = checkout;
}

std::optional<std::string> checkout_file_at(const std::string& commit, const std::string& relative_path) {
    // Both go into a shell command: a commit is hex, a recorded path has no quote.
    const bool hex = !commit.empty() && commit.find_first_not_of("0123456789abcdef") == std::string::npos;
    if (!hex || relative_path.empty() || relative_path.find('\'') != std::string::npos || relative_path.front() == '/')
        return std::nullopt;
    // Reading takes no lock in the checkout (another git command may be running there).
    const std::string git = git_command(run_checkout());
    const std::string command = git + "cat-file -e '" + commit + ":" + relative_path + "' 2>/dev/null && echo yes";
    if (command_output(command) != "yes") return std::nullopt;
    std::string out;
    if (FILE* pipe = popen((git + "show '" + commit + ":" + relative_path + "'").c_str(), "r")) {
        char buffer[4096];
        size_t n;
        while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, n);
        if (pclose(pipe) != 0) return std::nullopt;
    }
    return out;
}

std::string source_commit() {
    if (built_from_recorded_commit()) return CANOPY_BUILD_COMMIT;
    const std::string commit = git_head(source_checkout());
    return commit.empty() ? "unknown" : commit;
}

bool Environment::commit_mismatch() const {
    return !binary_commit.empty() && binary_commit != "unknown" && git_commit != "unknown" && binary_commit != git_commit;
}

std::string commit_text(const Environment& e) {
    std::string text = e.git_commit;
    if (e.git_dirty) {
        text += " (with uncommitted changes";
        for (size_t i = 0; i < e.dirty_files.size(); ++i) {
            if (i == 8) {
                text += fmt::format(" and {} more", e.dirty_files.size() - i);
                break;
            }
            text += (i == 0 ? ": " : ", ") + e.dirty_files[i];
        }
        text += ")";
    }
    if (e.commit_mismatch())
        text += fmt::format("; the binary was built from {}{}, not this checkout's commit", e.binary_commit,
                            e.binary_dirty ? " (with uncommitted changes)" : "");
    return text;
}

Environment collect_environment(const GpuContext& gpu, const std::string& config_hash) {
    Environment e;
    e.device = gpu.info();
    std::smatch match;
    if (std::regex_search(e.device.driver_info, match, std::regex(R"(Mesa (\d+\.\d+\.\d+))"))) e.mesa_version = match[1];
    e.nproc = std::thread::hardware_concurrency();
    const char* threads = std::getenv("LP_NUM_THREADS");
    e.lp_num_threads = threads ? threads : "unset";
    e.heap = heap_settings();
    e.cpu_model = cpu_model();
    e.cpu_mhz = cpu_mhz();
    const std::string governor = first_line("/sys/devices/system/cpu/cpu0/cpufreq/scaling_governor");
    e.cpu_scaling = !governor.empty() && governor != "performance";
    e.caches = cpu_caches();
    e.cpus_allowed = cpus_allowed();
    e.load_average = current_load_average();
    e.build_type = CANOPY_BUILD_TYPE;
    e.canopy_version = CANOPY_VERSION;
    e.binary_commit = source_commit();
    if (built_from_recorded_commit()) {
        // A bundle runs on a machine whose copy of the checkout is stale or absent: its own commit
        // is the run's.
        e.git_commit = e.binary_commit;
        e.git_dirty = e.binary_dirty = CANOPY_BUILD_DIRTY != 0;
    } else {
        const std::filesystem::path checkout = run_checkout();
        const std::string head = git_head(checkout);
        e.git_commit = head.empty() ? "unknown" : head;
        if (!head.empty()) e.dirty_files = changed_files(checkout);
        e.git_dirty = !e.dirty_files.empty();
        // The binary's checkout is usually the run's: its status is not read twice.
        std::error_code error;
        const bool same_checkout = std::filesystem::equivalent(checkout, source_checkout(), error);
        if (e.binary_commit != "unknown")
            e.binary_dirty = same_checkout ? e.git_dirty : !changed_files(source_checkout()).empty();
    }
    // A bundle's copy of the checkout has fresh file times and the bundle names its own commit.
    if (!built_from_recorded_commit()) e.binary_older_than = source_newer_than_this_binary();
    char host[256] = {};
    gethostname(host, sizeof host - 1);
    e.hostname = host;
    e.config_hash = config_hash;
    return e;
}

std::array<double, 3> current_load_average() {
    std::array<double, 3> load{};
    std::ifstream in("/proc/loadavg");
    in >> load[0] >> load[1] >> load[2];
    return load;
}

void to_json(nlohmann::json& j, const Environment& e) {
    nlohmann::json caches = nlohmann::json::array();
    for (const CpuCache& c : e.caches)
        caches.push_back({{"type", c.type}, {"level", c.level}, {"size", c.size_bytes}, {"num_sharing", c.num_sharing}});
    j = {{"device", e.device.name},
         {"device_type", e.device.type},
         {"driver", e.device.driver_name},
         {"driver_info", e.device.driver_info},
         {"mesa_version", e.mesa_version},
         {"vulkan_api", e.device.api_version},
         {"nproc", e.nproc},
         {"lp_num_threads", e.lp_num_threads},
         {"heap", e.heap},
         {"cpu_model", e.cpu_model},
         {"cpu_mhz", e.cpu_mhz},
         {"cpu_scaling", e.cpu_scaling},
         {"cpu_caches", caches},
         {"cpus_allowed", e.cpus_allowed},
         {"load_average", e.load_average},
         {"build_type", e.build_type},
         {"canopy_version", e.canopy_version},
         {"commit", e.git_commit},
         {"commit_dirty", e.git_dirty},
         {"commit_dirty_files", e.dirty_files},
         {"binary_commit", e.binary_commit},
         {"binary_commit_dirty", e.binary_dirty},
         {"commit_mismatch", e.commit_mismatch()},
         {"binary_older_than", e.binary_older_than},
         {"hostname", e.hostname},
         {"config_hash", e.config_hash}};
}

void from_json(const nlohmann::json& j, Environment& e) {
    auto read = [&](const char* key, auto& field) {
        if (j.contains(key) && !j.at(key).is_null()) j.at(key).get_to(field);
    };
    read("device", e.device.name);
    read("device_type", e.device.type);
    read("driver", e.device.driver_name);
    read("driver_info", e.device.driver_info);
    read("mesa_version", e.mesa_version);
    read("vulkan_api", e.device.api_version);
    read("nproc", e.nproc);
    read("lp_num_threads", e.lp_num_threads);
    read("heap", e.heap);
    read("cpu_model", e.cpu_model);
    read("cpu_mhz", e.cpu_mhz);
    read("cpu_scaling", e.cpu_scaling);
    read("cpus_allowed", e.cpus_allowed);
    read("load_average", e.load_average);
    read("build_type", e.build_type);
    read("canopy_version", e.canopy_version);
    read("commit", e.git_commit);
    read("commit_dirty", e.git_dirty);
    read("commit_dirty_files", e.dirty_files);
    read("binary_commit", e.binary_commit);
    read("binary_commit_dirty", e.binary_dirty);
    read("binary_older_than", e.binary_older_than);
    read("hostname", e.hostname);
    read("config_hash", e.config_hash);
    if (j.contains("cpu_caches"))
        for (const auto& c : j.at("cpu_caches"))
            e.caches.push_back({c.at("type").get<std::string>(), c.at("level").get<int>(), c.at("size").get<long long>(),
                                c.at("num_sharing").get<int>()});
}

std::string utc_now() { return fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", fmt::gmtime(std::time(nullptr))); }

}  // namespace canopy
