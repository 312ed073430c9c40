#include "support/quiet_run.hpp"

#include "core/registry.hpp"
#include "run/experiment_runner.hpp"
#include "support/test_gpu.hpp"

namespace canopy::test {

RunRecord quiet_run(const Experiment& experiment, const std::filesystem::path& out_dir,
                    const std::filesystem::path& reference_cache_dir) {
    const TechniqueRegistry& registry = TechniqueRegistry::instance();
    const PreparedExperiment prepared = prepare_experiment(experiment, registry, gpu());
    RunOptions options;
    options.out_dir = out_dir;
    options.show_progress = false;
    options.images = ImageOutput::none;
    options.reference_cache_dir = reference_cache_dir;
    return run_experiment(prepared, registry, gpu(), options);
}

}  // namespace canopy::test
