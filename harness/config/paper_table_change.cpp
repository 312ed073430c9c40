#include "config/paper_table_change.hpp"

#include "config/experiment_config.hpp"
#include "config/toml_reader.hpp"

#include <fmt/format.h>

namespace canopy {

std::string paper_table_only_change(const Experiment& now, const std::filesystem::path& file_now,
                                    const std::string& text_at_run, const std::string& recorded_hash) {
    const std::string hash_at_run = hash_files(text_at_run, now.hashed_files);
    if (hash_at_run != recorded_hash)
        return fmt::format("the experiment at the run's commit hashes with today's scene files to {}, the run recorded "
                           "{}: a scene, mesh or map changed since, or the run's config was not committed",
                           hash_at_run, recorded_hash);
    toml::table a = parse_toml(text_at_run, file_now), b = parse_toml_file(file_now);
    a.erase("paper");
    b.erase("paper");
    if (a != b) return "the experiment differs from the run's outside its [paper] table: measure it again";
    return "";
}

}  // namespace canopy
