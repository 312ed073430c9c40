#include "run/environment.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <thread>
#include <unistd.h>

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

std::string git_command() { return std::string("git -C '") + CANOPY_SOURCE_DIR + "' "; }

}  // namespace

std::string canopy_build_type() { return CANOPY_BUILD_TYPE; }

std::filesystem::path source_checkout() { return CANOPY_SOURCE_DIR; }

std::string source_commit() {
    const std::string commit = command_output(git_command() + "rev-parse HEAD 2>/dev/null");
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
    e.cpu_model = cpu_model();
    e.build_type = CANOPY_BUILD_TYPE;
    e.canopy_version = CANOPY_VERSION;
    e.git_commit = source_commit();
    if (e.git_commit != "unknown")
        e.git_dirty = !command_output(git_command() + "status --porcelain --untracked-files=no 2>/dev/null").empty();
    char host[256] = {};
    gethostname(host, sizeof host - 1);
    e.hostname = host;
    e.config_hash = config_hash;
    return e;
}

void to_json(nlohmann::json& j, const Environment& e) {
    j = {{"device", e.device.name},
         {"device_type", e.device.type},
         {"driver", e.device.driver_name},
         {"driver_info", e.device.driver_info},
         {"mesa_version", e.mesa_version},
         {"vulkan_api", e.device.api_version},
         {"nproc", e.nproc},
         {"lp_num_threads", e.lp_num_threads},
         {"cpu_model", e.cpu_model},
         {"build_type", e.build_type},
         {"canopy_version", e.canopy_version},
         {"commit", e.git_commit},
         {"commit_dirty", e.git_dirty},
         {"hostname", e.hostname},
         {"config_hash", e.config_hash}};
}

}  // namespace canopy
