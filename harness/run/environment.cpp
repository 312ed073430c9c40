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
// refresh the index under .git/index.lock, colliding with the user's own git commands).
std::string git_command() { return std::string("GIT_OPTIONAL_LOCKS=0 git -C '") + CANOPY_SOURCE_DIR + "' "; }

std::string git_head() { return command_output(git_command() + "rev-parse HEAD 2>/dev/null"); }

}  // namespace

std::string canopy_build_type() { return CANOPY_BUILD_TYPE; }

std::filesystem::path source_checkout() { return CANOPY_SOURCE_DIR; }

std::optional<std::string> checkout_file_at(const std::string& commit, const std::string& relative_path) {
    // Both go into a shell command: a commit is hex, a recorded path has no quote.
    const bool hex = !commit.empty() && commit.find_first_not_of("0123456789abcdef") == std::string::npos;
    if (!hex || relative_path.empty() || relative_path.find('\'') != std::string::npos || relative_path.front() == '/')
        return std::nullopt;
    // Reading takes no lock in the checkout (another git command may be running there).
    const std::string command = git_command() + "cat-file -e '" + commit + ":" + relative_path +
                                "' 2>/dev/null && echo yes";
    if (command_output(command) != "yes") return std::nullopt;
    std::string out;
    if (FILE* pipe = popen((git_command() + "show '" + commit + ":" + relative_path + "'").c_str(), "r")) {
        char buffer[4096];
        size_t n;
        while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, n);
        if (pclose(pipe) != 0) return std::nullopt;
    }
    return out;
}

// A bundle (scripts/gpu-bundle) is configured with the commit it is built from: that, not the git
// state of the copy it runs in (stale or absent on the machine it travels to), says which code ran.
bool built_from_recorded_commit() { return *CANOPY_BUILD_COMMIT != '\0'; }

std::string source_commit() {
    if (built_from_recorded_commit()) return CANOPY_BUILD_COMMIT;
    const std::string commit = git_head();
    return commit.empty() ? "unknown" : commit;
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
    e.git_commit = source_commit();
    // Changes to the sources, not to results/: regenerating committed results rewrites tracked files
    // there (--force removes a folder's old outputs first), which says nothing about the code.
    if (built_from_recorded_commit())
        e.git_dirty = CANOPY_BUILD_DIRTY != 0;
    else if (e.git_commit != "unknown")
        e.git_dirty = !command_output(git_command() +
                                      "status --porcelain --untracked-files=no -- . ':(exclude)results' 2>/dev/null")
                           .empty();
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
