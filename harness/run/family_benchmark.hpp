// Benchmarks a technique family defines for what only it has (`canopy bench <name>`; e.g. the
// grass family's mip filters on its baked slices): measurements, not timed tests. Each declares
// typed parameters as a technique does, and registers itself by name at static-initialisation
// time; the harness gives it a device and a scene, prints its Markdown and writes it with its
// numbers and the run's environment. Registration is separate from running.
#pragma once

#include "core/param.hpp"
#include "gpu/context.hpp"
#include "scene/scene.hpp"

#include <nlohmann/json.hpp>

#include <memory>
#include <string>
#include <vector>

namespace canopy {

struct FamilyBenchmarkResult {
    std::string markdown;    // the tables, as a researcher pastes them
    nlohmann::json numbers;  // every number in them
};

class FamilyBenchmark {
public:
    virtual ~FamilyBenchmark() = default;
    virtual std::string name() const = 0;     // `canopy bench <name>`
    virtual std::string summary() const = 0;  // one line for --help
    // The scene it runs on when none is given, relative to the checkout (configs/scenes/...).
    virtual std::string default_scene() const = 0;
    virtual std::vector<ParamSpec> params() const = 0;
    virtual FamilyBenchmarkResult run(const GpuContext& gpu, const Scene& scene, const ParamSet& params) const = 0;
};

class FamilyBenchmarkRegistry {
public:
    static FamilyBenchmarkRegistry& instance();
    void add(std::unique_ptr<FamilyBenchmark> benchmark);  // throws std::logic_error on a duplicate name
    std::vector<const FamilyBenchmark*> all() const;       // sorted by name

private:
    std::vector<std::unique_ptr<FamilyBenchmark>> benchmarks_;
};

template <typename T>
struct RegisterFamilyBenchmark {
    RegisterFamilyBenchmark() { FamilyBenchmarkRegistry::instance().add(std::make_unique<T>()); }
};

}  // namespace canopy
