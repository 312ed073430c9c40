#include "run/family_benchmark_run.hpp"

#include "config/scene_config.hpp"
#include "core/error.hpp"
#include "report/atomic_file.hpp"
#include "run/environment.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace canopy {

std::map<std::string, ParamValue> parse_benchmark_params(const std::vector<ParamSpec>& specs,
                                                         const std::map<std::string, std::string>& given) {
    std::map<std::string, ParamValue> values;
    for (const auto& entry : given) {
        // Named copies: clang before 16 refuses lambdas that capture structured bindings.
        const std::string& name = entry.first;
        const std::string& text = entry.second;
        const auto spec = std::find_if(specs.begin(), specs.end(), [&](const ParamSpec& s) { return s.name == name; });
        if (spec == specs.end()) throw ConfigError({}, 0, fmt::format("unknown parameter --{}", name));
        const auto refuse = [&]() {
            return ConfigError({}, 0, fmt::format("--{} {}: expected {}", name, text, spec->type_and_range()),
                               fmt::format("--{} takes a {}", name, spec->type_and_range()));
        };
        try {
            size_t used = 0;
            switch (spec->type) {
                case ParamType::integer: values[name] = std::stoll(text, &used); break;
                case ParamType::real: values[name] = std::stod(text, &used); break;
                case ParamType::boolean:
                    if (text != "true" && text != "false") throw refuse();
                    values[name] = text == "true";
                    used = text.size();
                    break;
                case ParamType::choice:
                case ParamType::path: values[name] = text; used = text.size(); break;
            }
            if (used != text.size()) throw refuse();
        } catch (const std::logic_error&) {  // stoll / stod: nothing or out of range
            throw refuse();
        }
    }
    return values;
}

int run_family_benchmark(const FamilyBenchmark& benchmark, const std::filesystem::path& scene_file,
                         const std::map<std::string, std::string>& given, const std::string& device,
                         const std::filesystem::path& out) {
    const Scene scene = load_scene(scene_file);
    const ParamSet params = ParamSet::resolve(benchmark.params(), parse_benchmark_params(benchmark.params(), given),
                                              {}, {}, "bench " + benchmark.name());
    GpuContext gpu(device);
    const FamilyBenchmarkResult result = benchmark.run(gpu, scene, params);
    const Environment environment = collect_environment(gpu, "");
    fmt::print("{}", result.markdown);
    if (out.empty()) return 0;
    nlohmann::json json;
    json["benchmark"] = benchmark.name();
    json["scene"] = scene.name;
    json["scene_file"] = scene_file.string();
    nlohmann::json p = nlohmann::json::object();
    for (const auto& [name, value] : params.values()) p[name] = to_string(value);
    json["params"] = p;
    json["environment"] = environment;
    json["numbers"] = result.numbers;
    const std::string footer =
        fmt::format("\ncanopy {} on {} ({}), {}, nproc {}, LP_NUM_THREADS {}, commit {}; `canopy bench {}` {} on {}.\n",
                    environment.canopy_version, environment.device.name, environment.device.driver_info,
                    environment.cpu_model, environment.nproc, environment.lp_num_threads, commit_text(environment), benchmark.name(), params.summary(),
                    scene_file.string());
    std::filesystem::create_directories(out);
    write_text_atomically(out / (benchmark.name() + ".json"), json.dump(2) + "\n");
    write_text_atomically(out / (benchmark.name() + ".md"), result.markdown + footer);
    fmt::print("{}\nwritten to {}\n", footer, std::filesystem::absolute(out).string());
    return 0;
}

}  // namespace canopy
