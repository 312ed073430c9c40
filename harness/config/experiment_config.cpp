#include "config/experiment_config.hpp"

#include "scene/population_kind.hpp"

#include "config/camera_path_config.hpp"
#include "config/file_name_rules.hpp"
#include "config/scene_config.hpp"
#include "config/paper_config.hpp"
#include "config/population_overrides.hpp"
#include "config/toml_reader.hpp"
#include "metrics/metric_registry.hpp"
#include "scene/scene_limits.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>
#include <sstream>
#include <optional>
#include <set>

namespace canopy {

uint64_t fnv1a_64(std::string_view bytes, uint64_t state) {
    for (unsigned char byte : bytes) {
        state ^= byte;
        state *= 0x100000001b3ull;
    }
    return state;
}

namespace {

constexpr int kMaxResolution = 8192;
constexpr long long kMaxFrames = 1000000;
constexpr uint64_t kMaxCases = 100000;

const char* const kExperimentExample =
    "[experiment]\n    scenes = [\"../scenes/spheres.toml\"]\n\n    [[technique]]\n    name = \"shadow.pcf\"";

// A scene variant's overrides: its name, the width of its shadow light (a rect's side, a
// sphere's diameter: the width penumbra estimates use), e.g. to sweep the light size (Fig 6.9),
// whether its objects cast shadows (false: a shadow-free variant, where every technique's
// visibility should be 1 wherever the light reaches), whether its first light does, the first
// light's direction (directional lights), and its
// camera (keys of [camera] given replace the scene's).
void apply_scene_variant(TomlReader& variant, Scene& scene) {
    scene.name = variant.get_string("name", scene.name);
    if (const auto problem = file_name_problem(scene.name))
        throw variant.error("name", fmt::format("the scene variant's name {} cannot be used: {}", printable_name(scene.name),
                                                *problem),
                            fmt::format("scene names become file names and case ids: use {}", kFileNameRule));
    // Whether the scene's first light casts shadows: a grass scene's "local" (false: no
    // blade-on-blade shadowing) and "shadowed" (true) reference modes from one scene file.
    // Before light_size, which resizes the shadow-casting light this may make.
    if (variant.has("light_casts_shadows"))
        scene.lights.front().casts_shadows = variant.get_bool("light_casts_shadows", true);
    // Its first light's direction: a directional sun at another elevation (e.g. a sweep of it).
    if (variant.has("light_direction")) {
        Light& light = scene.lights.front();
        if (light.type != LightType::directional)
            throw variant.error("light_direction", fmt::format("scene '{}''s first light is not directional", scene.name),
                                "light_direction moves a directional sun: make it the scene's first [[light]]");
        light.direction = read_direction(variant, "light_direction", light.direction,
                                         "the variant's 'light_direction' is the zero vector",
                                         "give the direction the light travels, e.g. light_direction = [-0.4, -0.8, -0.45]");
    }
    if (variant.has("light_size")) {
        const double size = variant.get_float("light_size", 0.0);
        // A rect's side or a sphere's diameter, within the limits of a light's size (scene_limits.hpp).
        const double min = 2.0 * limits::kMinLightSize, max = limits::kMaxLightSize;
        if (!(size >= min && size <= max))
            throw variant.error("light_size", fmt::format("'light_size' must lie in [{}, {}], got {}", min, max, size),
                                "light_size = 0.5");
        Light* light = nullptr;
        for (Light& l : scene.lights)
            if (l.casts_shadows && !light) light = &l;
        if (!light || !light->is_area())
            throw variant.error("light_size", fmt::format("scene '{}' has no area light to resize", scene.name),
                                "light_size applies to a shadow-casting rect or sphere light");
        if (light->type == LightType::rect) light->rect_size = glm::vec2(float(size));
        else light->sphere_radius = float(0.5 * size);
    }
    // Another view of the same scene (e.g. a grass field seen near, mid-distance and far).
    if (std::optional<TomlReader> camera = variant.get_table("camera", "the scene variant's camera")) {
        read_scene_camera(*camera, scene.camera);
        camera->finish();
    }
    if (variant.has("casts_shadows")) {
        const bool casts = variant.get_bool("casts_shadows", true);
        for (Object& object : scene.objects) object.casts_shadows = casts;
        for (Population& population : scene.populations) population.prototype.casts_shadows = casts;
    }
    // Parameters of a family's populations, by population name, replacing the scene's (e.g. a
    // quick variant of a field with fewer, wider blades); the copies are generated again.
    if (std::optional<TomlReader> populations = variant.get_table("populations", "the scene variant's populations")) {
        for (auto&& [key, value] : populations->table()) {
            const std::string name(key.str());
            auto it = std::find_if(scene.populations.begin(), scene.populations.end(),
                                   [&](const Population& p) { return p.name == name; });
            std::vector<std::string> names;
            for (const Population& p : scene.populations) names.push_back(p.name);
            if (it == scene.populations.end()) {
                const std::string near = closest_match(name, names);
                throw populations->error_at(value, fmt::format("scene '{}' has no population '{}'", scene.name, name),
                                            near.empty() ? "name one of the scene's [[population]] entries"
                                                         : fmt::format("did you mean '{}'?", near));
            }
            std::optional<TomlReader> overrides = populations->get_table(name, fmt::format("population '{}'", name));
            if (!overrides) continue;
            std::map<std::string, ParamValue> given;
            std::map<std::string, int> lines;
            for (auto&& [param, param_value] : overrides->table()) {
                if (!is_param_scalar(param_value))
                    throw overrides->error_at(param_value, fmt::format("parameter '{}' must be one value", param.str()),
                                              "`canopy list` shows each population kind's parameters");
                given[std::string(param.str())] = to_param_value(param_value);
                lines[std::string(param.str())] = int(param.source().begin.line);
                overrides->node(param.str());  // read: finish() names only keys nobody read
            }
            overrides->finish();
            override_population_params(*it, given, lines, SourceLocation{variant.file(), variant.line()});
        }
        populations->finish();
    }
    variant.finish();
}

std::vector<Scene> read_scenes(TomlReader& reader, std::vector<std::filesystem::path>& scene_files) {
    const toml::node* node = reader.node("scenes");
    const std::string example = "scenes = [\"../scenes/spheres.toml\"]";
    if (!node)
        throw ConfigError(reader.file(), reader.line(), "[experiment] needs 'scenes', the scene files to render",
                          fmt::format("add a line such as: {}", example));
    const toml::array* array = node->as_array();
    if (!array)
        throw reader.error_at(*node, fmt::format("'scenes' must be an array of file names, got {}", describe_node(*node)),
                              fmt::format("write it as: {}", example));
    if (array->empty())
        throw reader.error_at(*node, "'scenes' must name at least one scene file", fmt::format("write it as: {}", example));

    const std::filesystem::path folder = reader.file().parent_path();
    std::vector<Scene> scenes;
    std::map<std::string, int> listed;  // scene name -> the line that first lists it
    size_t index = 0;
    for (const toml::node& element : *array) {
        ++index;
        // A file name, or a variant: { file = "...", name = "...", light_size = 0.5 }.
        const toml::node* file_node = &element;
        std::optional<TomlReader> variant;
        if (const toml::table* table = element.as_table()) {
            variant.emplace(*table, reader.file(), fmt::format("scenes entry #{}", index));
            file_node = variant->node("file");
            if (!file_node)
                throw variant->error("file", "a scene variant needs 'file'",
                                     "write it as: { file = \"../scenes/at-at.toml\", name = \"at-at-small\", light_size = 0.4 } "
                                     "or { file = \"../scenes/at-at.toml\", name = \"at-at-unshadowed\", casts_shadows = false }");
        }
        const auto* name = file_node->as_string();
        if (!name)
            throw reader.error_at(*file_node, fmt::format("'scenes' must hold file names (strings) or variant tables, got {}",
                                                          describe_node(*file_node)),
                                  fmt::format("write it as: {}", example));
        const std::filesystem::path scene_file = (folder / name->get()).lexically_normal();
        std::error_code ignored;
        if (std::filesystem::is_directory(scene_file, ignored))
            throw reader.error_at(*file_node, fmt::format("scene file '{}' is a directory ({}), not a scene file",
                                                          name->get(), scene_file.string()),
                                  "name the scene's .toml file inside it, e.g. \"../scenes/spheres.toml\"");
        if (!std::filesystem::is_regular_file(scene_file, ignored))
            throw reader.error_at(*file_node, fmt::format("scene file '{}' not found (looked for {})", name->get(),
                                                          scene_file.string()),
                                  std::filesystem::path(name->get()).is_absolute()
                                      ? "check the path, or give it relative to the experiment file's folder"
                                      : "scene paths are relative to the experiment file's folder");
        Scene scene = load_scene(scene_file);  // its errors carry the scene file's own file:line
        if (variant) {
            apply_scene_variant(*variant, scene);
            std::ostringstream text;
            text << *element.as_table();
            scene.variant = text.str();
            std::replace(scene.variant.begin(), scene.variant.end(), '\n', ' ');
        }
        // Groups and case ids are named after the scene: two of one name would measure it twice under one heading.
        if (const auto first = listed.find(scene.name); first != listed.end())
            throw reader.error_at(element, fmt::format("scene '{}' is listed twice (first at line {}): its cases would be "
                                                       "measured twice under one heading",
                                                       scene.name, first->second),
                                  "remove this listing, or make it a variant with a name of its own: { file = \"...\", "
                                  "name = \"...\", light_size = 0.5 }");
        listed.emplace(scene.name, line_of(element));
        scenes.push_back(std::move(scene));
        scene_files.push_back(scene_file);
    }
    return scenes;
}

std::vector<Resolution> read_resolutions(TomlReader& reader, std::vector<Resolution> fallback) {
    const toml::node* node = reader.node("resolutions");
    if (!node) return fallback;
    const std::string hint = "write it as: resolutions = [[640, 360], [1280, 720]]";
    const toml::array* array = node->as_array();
    if (!array || array->empty())
        throw reader.error_at(*node, "'resolutions' must be a non-empty array of [width, height] pairs", hint);
    std::vector<Resolution> resolutions;
    for (const toml::node& element : *array) {
        const toml::array* pair = element.as_array();
        if (!pair || pair->size() != 2 || !pair->get(0)->is_integer() || !pair->get(1)->is_integer())
            throw reader.error_at(element, "each resolution must be a [width, height] pair of integers", hint);
        const long long width = pair->get(0)->as_integer()->get(), height = pair->get(1)->as_integer()->get();
        if (width < 1 || width > kMaxResolution || height < 1 || height > kMaxResolution)
            throw reader.error_at(element, fmt::format("resolution {}x{} is out of range", width, height),
                                  fmt::format("width and height must lie in [1, {}]", kMaxResolution));
        resolutions.push_back({int(width), int(height)});
    }
    return resolutions;
}

// Reads [technique.params]: each value a scalar or an array of scalars (a sweep). Every value is
// checked against the technique's specs now, so bad values fail before anything runs.
void read_params(TomlReader& params, TechniqueEntry& entry, const Technique& technique) {
    std::vector<std::pair<const toml::key*, const toml::node*>> in_file_order;
    for (auto&& [key, value] : params.table()) in_file_order.emplace_back(&key, &value);
    std::sort(in_file_order.begin(), in_file_order.end(), [](const auto& a, const auto& b) {
        const auto &pa = a.first->source().begin, &pb = b.first->source().begin;
        return pa.line != pb.line ? pa.line < pb.line : pa.column < pb.column;
    });

    const std::vector<ParamSpec> specs = technique.params();
    for (const auto& [key, value] : in_file_order) {
        const std::string name(key->str());
        const int key_line = int(key->source().begin.line);
        std::vector<std::pair<ParamValue, int>> values;  // with each value's own line
        const std::string hint = fmt::format("give one value ({0} = 5) or a list to sweep ({0} = [3, 5, 7])", name);
        if (const toml::array* array = value->as_array()) {
            if (array->empty())
                throw params.error_at(*value, fmt::format("parameter '{}' of {} has an empty list of values", name,
                                                          entry.name), hint);
            for (const toml::node& element : *array) {
                if (!is_param_scalar(element))
                    throw params.error_at(element, fmt::format("parameter '{}' of {}: a sweep holds only numbers, "
                                                               "booleans or strings, got {}",
                                                               name, entry.name, describe_node(element)),
                                          hint);
                values.emplace_back(to_param_value(element), line_of(element));
            }
        } else if (is_param_scalar(*value)) {
            values.emplace_back(to_param_value(*value), key_line);
        } else {
            throw params.error_at(*value, fmt::format("parameter '{}' of {} must be a value or a list of values, got {}",
                                                      name, entry.name, describe_node(*value)),
                                  hint);
        }

        for (const auto& [param, line] : values)
            ParamSet::resolve(specs, {{name, param}}, {{name, line > 0 ? line : key_line}}, entry.where, entry.name);

        for (auto& [param, line] : values) entry.sweep[name].push_back(std::move(param));
        entry.param_lines[name] = key_line;
        entry.param_order.push_back(name);
    }
}

TechniqueEntry read_technique(TomlReader& reader, const TechniqueRegistry& registry) {
    TechniqueEntry entry;
    entry.where = reader.where();
    entry.name = reader.require_string("name", "\"shadow.pcf\"");
    const Technique* technique = registry.find(entry.name);
    if (!technique) {
        const std::string suggestion = closest_match(entry.name, registry.names());
        const std::vector<std::string> names = registry.names();
        std::string hint = suggestion.empty() ? "" : fmt::format("did you mean '{}'? ", suggestion);
        if (suggestion.empty() && !names.empty() && names.size() <= 12)
            hint += fmt::format("known techniques: {}; ", fmt::join(names, ", "));
        hint += "run `canopy list` to see every technique and its parameters";
        throw reader.error("name", fmt::format("unknown technique '{}'", entry.name), hint);
    }
    if (std::optional<TomlReader> params = reader.get_table("params", "[technique.params]"))
        read_params(*params, entry, *technique);
    reader.finish();
    return entry;
}

// A sweep's cases multiply: a few lists of a few hundred values would take years to run, and
// memory to expand. Counted without expanding, saturating instead of overflowing.
void check_case_count(const Experiment& experiment) {
    const auto times = [](uint64_t a, uint64_t b) { return b != 0 && a > kMaxCases / b ? kMaxCases + 1 : a * b; };
    const uint64_t per_entry_factor = times(experiment.scenes.size(), experiment.resolutions.size());
    uint64_t total = 0, largest = 0;
    const TechniqueEntry* largest_entry = nullptr;
    for (const TechniqueEntry& entry : experiment.techniques) {
        uint64_t combinations = 1;
        for (const auto& [key, values] : entry.sweep) combinations = times(combinations, std::max<size_t>(values.size(), 1));
        const uint64_t cases = times(combinations, per_entry_factor);
        total = std::min(total + cases, kMaxCases + 1);
        if (cases >= largest) largest = cases, largest_entry = &entry;
    }
    if (total <= kMaxCases || !largest_entry) return;
    throw ConfigError(largest_entry->where.file, largest_entry->where.line,
                      fmt::format("the experiment expands to more than {} cases", kMaxCases),
                      fmt::format("scenes x resolutions x the product of each [[technique]]'s lists; sweep fewer "
                                  "values, or split the experiment (this [[technique]] alone gives {}{})",
                                  largest > kMaxCases ? "more than " : "", std::min(largest, kMaxCases)));
}

// The entry's swept parameters in config order; entries built in code may lack param_order.
std::vector<std::string> ordered_keys(const TechniqueEntry& entry) {
    std::vector<std::string> keys;
    for (const std::string& key : entry.param_order)
        if (entry.sweep.count(key) && std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
    for (const auto& [key, values] : entry.sweep)
        if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
    std::erase_if(keys, [&](const std::string& key) { return entry.sweep.at(key).empty(); });
    return keys;
}

// Moves to the next combination of the sweep (last key fastest); false after the last one.
bool advance(std::vector<size_t>& choice, const std::vector<std::string>& keys, const TechniqueEntry& entry) {
    for (size_t k = keys.size(); k-- > 0;) {
        if (++choice[k] < entry.sweep.at(keys[k]).size()) return true;
        choice[k] = 0;
    }
    return false;
}

// A technique with the same parameters twice (two [[technique]] entries alike, or sweeps that
// overlap) would measure identical cases under one heading: refused at the second entry's line.
void refuse_repeated_cases(const Experiment& experiment, const TechniqueRegistry& registry) {
    std::map<std::pair<std::string, std::string>, const TechniqueEntry*> first;  // (technique, parameters) -> entry
    for (const TechniqueEntry& entry : experiment.techniques) {
        const Technique* technique = registry.find(entry.name);
        if (!technique) continue;
        const std::vector<std::string> keys = ordered_keys(entry);
        const std::vector<ParamSpec> specs = technique->params();
        std::vector<size_t> choice(keys.size(), 0);
        do {
            std::map<std::string, ParamValue> given;
            for (size_t k = 0; k < keys.size(); ++k) given[keys[k]] = entry.sweep.at(keys[k])[choice[k]];
            const std::string parameters = ParamSet::resolve(specs, given, {}, entry.where, entry.name).summary();
            const auto [earlier, added] = first.emplace(std::pair(entry.name, parameters), &entry);
            if (added) continue;
            if (earlier->second == &entry)
                throw ConfigError(entry.where.file, entry.where.line,
                                  fmt::format("[[technique]] {} gives the same parameters twice ({}): a list holds one "
                                              "value twice, so its cases would be measured twice",
                                              entry.name, parameters),
                                  "list each value once");
            throw ConfigError(entry.where.file, entry.where.line,
                              fmt::format("[[technique]] {} repeats the parameters of the [[technique]] at line {} ({}): "
                                          "its cases would be measured twice under one heading",
                                          entry.name, earlier->second->where.line, parameters),
                              "remove this entry, or give it other parameters (a list sweeps a parameter: kernel = [3, 5, 7])");
        } while (advance(choice, keys, entry));
    }
}

// [reference]: whether and how precisely to ray-trace the ground truth.
void read_reference(TomlReader& section, Experiment& experiment) {
    experiment.reference_enabled = section.get_bool("enabled", experiment.reference_enabled);
    const long long light_samples = section.get_int("light_samples", experiment.reference.light_samples);
    if (light_samples < 1 || light_samples > 65536)
        throw section.error("light_samples", fmt::format("'light_samples' must lie in [1, 65536], got {}", light_samples),
                            "shadow rays per pixel sample towards an area light, e.g. light_samples = 64");
    const long long pixel_samples = section.get_int("pixel_samples", experiment.reference.pixel_samples);
    if (pixel_samples < 1 || pixel_samples > 1024)
        throw section.error("pixel_samples", fmt::format("'pixel_samples' must lie in [1, 1024], got {}", pixel_samples),
                            "sub-pixel samples per pixel (anti-aliasing), e.g. pixel_samples = 4");
    const long long seed = section.get_int("seed", (long long)experiment.reference.seed);
    if (seed < 0) throw section.error("seed", "'seed' must not be negative", "seed = 1");
    experiment.reference.light_samples = int(light_samples);
    experiment.reference.pixel_samples = int(pixel_samples);
    experiment.reference.seed = uint64_t(seed);
    if (section.has("distance_bands")) {
        const glm::vec2 bands = section.get_vec2("distance_bands", {}, Broadcast::forbidden);
        if (!(bands.x >= 0.0f && bands.x <= bands.y))
            throw section.error("distance_bands",
                                fmt::format("'distance_bands' must be two distances 0 <= near-to-middle <= middle-to-far, "
                                            "got [{}, {}]", bands.x, bands.y),
                                "distance_bands = [8, 30]: FLIP near (under 8 m from the eye), in the middle and far "
                                "(from 30 m), by the distance of the surface the reference sees through each pixel");
        // The values as written (get_vec2 checked their shape and order in float).
        const toml::array& written = *section.node("distance_bands")->as_array();
        experiment.distance_bands = DistanceBands{written[0].value<double>().value(), written[1].value<double>().value()};
    }
    section.finish();
}

}  // namespace

std::string hash_files(const std::string& experiment_bytes, const std::vector<std::filesystem::path>& files) {
    uint64_t hash = fnv1a_64(experiment_bytes);
    for (const std::filesystem::path& file : files) hash = fnv1a_64(read_config_file(file), hash);
    return fmt::format("{:016x}", hash);
}


const char* to_string(BaselinePairing pairing) { return pairing == BaselinePairing::round ? "round" : "adjacent"; }

Experiment load_experiment(const std::filesystem::path& file, const TechniqueRegistry& registry) {
    const std::string text = read_config_file(file);
    const toml::table root = parse_toml(text, file);
    TomlReader top(root, file, "");
    std::optional<TomlReader> section = top.get_table("experiment", "[experiment]");
    std::vector<TomlReader> technique_sections = top.get_tables("technique", "[[technique]]");
    std::optional<TomlReader> reference_section = top.get_table("reference", "[reference]");
    std::optional<TomlReader> paper_section = top.get_table("paper", "[paper]");
    std::optional<TomlReader> path_section = top.get_table("camera_path", "[camera_path]");
    top.finish();
    if (!section)
        throw ConfigError(file, 0, "missing the [experiment] section",
                          fmt::format("an experiment file starts like this:\n    {}", kExperimentExample));

    Experiment experiment;
    experiment.file = file;
    experiment.name = section->get_string("name", file.stem().string());
    if (experiment.name.empty())
        throw section->error("name", "the experiment name must not be empty", "name = \"shadow-filtering\"");
    if (const auto problem = file_name_problem(experiment.name)) {
        const std::string hint = fmt::format("the experiment's name becomes its output folder's name: use {}", kFileNameRule);
        if (section->has("name"))
            throw section->error("name", fmt::format("the experiment name {} cannot be used: {}",
                                                     printable_name(experiment.name), *problem), hint);
        throw ConfigError(file, section->line(),
                          fmt::format("the experiment has no name, and its file name {} cannot be used as one: {}",
                                      printable_name(experiment.name), *problem),
                          "add name = \"...\" to [experiment]; " + hint);
    }
    experiment.description = section->get_string("description", "");
    experiment.resolutions = read_resolutions(*section, experiment.resolutions);
    const long long warmup = section->get_int("warmup", experiment.warmup_frames);
    if (warmup < 0 || warmup > kMaxFrames)
        throw section->error("warmup", fmt::format("'warmup' must lie in [0, {}], got {}", kMaxFrames, warmup),
                             "warmup is the number of unmeasured frames before timing, e.g. warmup = 5");
    const long long repetitions = section->get_int("repetitions", experiment.rounds);
    if (repetitions < 1 || repetitions > kMaxFrames)
        throw section->error("repetitions",
                             fmt::format("'repetitions' must lie in [1, {}], got {}", kMaxFrames, repetitions),
                             "repetitions is the number of measured rounds (samples per case), e.g. repetitions = 20");
    const long long frames_per_sample = section->get_int("frames_per_sample", experiment.frames_per_sample);
    if (frames_per_sample < 1 || frames_per_sample > kMaxFrames / repetitions)
        throw section->error("frames_per_sample",
                             fmt::format("'frames_per_sample' must lie in [1, {}] (repetitions x frames_per_sample "
                                         "<= {}), got {}",
                                         kMaxFrames / repetitions, kMaxFrames, frames_per_sample),
                             "frames_per_sample is the number of frames one timing sample averages, e.g. "
                             "frames_per_sample = 4");
    const std::string pairing = section->get_string("pairing", to_string(experiment.pairing));
    if (pairing != "adjacent" && pairing != "round")
        throw section->error("pairing", fmt::format("'pairing' must be \"adjacent\" or \"round\", got \"{}\"", pairing),
                             "pairing = \"adjacent\" divides each sample by the baseline samples just before and after "
                             "it (the default); \"round\" by the baseline's one sample of the round");
    experiment.pairing = pairing == "round" ? BaselinePairing::round : BaselinePairing::adjacent;
    experiment.warmup_frames = int(warmup);
    experiment.rounds = int(repetitions);
    experiment.frames_per_sample = int(frames_per_sample);
    if (reference_section) read_reference(*reference_section, experiment);
    if (paper_section) experiment.paper = read_paper(*paper_section, registry);
    if (experiment.paper && !experiment.distance_bands)
        for (const PaperClaim& claim : experiment.paper->claims)
            if (const MetricInfo* metric = find_claim_metric(claim.metric); metric && metric->band != DistanceBand::none)
                throw ConfigError(claim.where.file, claim.where.line,
                                  fmt::format("the claim compares '{}', which needs the experiment's distance bands",
                                              claim.metric),
                                  "add distance_bands = [near-to-middle, middle-to-far] to [reference], e.g. "
                                  "distance_bands = [8, 30]");

    std::vector<std::filesystem::path> hashed_files;
    experiment.scenes = read_scenes(*section, hashed_files);
    section->finish();
    if (path_section) {
        experiment.camera_path = read_camera_path(*path_section, experiment.scenes);
        if (experiment.frames_per_sample != 1)
            throw section->error("frames_per_sample",
                                 "'frames_per_sample' cannot be combined with [camera_path]: with a path, one sample "
                                 "is one traversal of its frames",
                                 "remove frames_per_sample, or set [camera_path] frames to the frames a sample should span");
    }

    if (technique_sections.empty())
        throw ConfigError(file, 0, "the experiment has no [[technique]] entries",
                          "add one per technique to run, e.g.\n    [[technique]]\n    name = \"shadow.pcf\"\n"
                          "run `canopy list` to see every technique");
    for (TomlReader& technique_section : technique_sections)
        experiment.techniques.push_back(read_technique(technique_section, registry));
    check_case_count(experiment);
    refuse_repeated_cases(experiment, registry);

    // The files a scene reads (meshes, height maps, a population's maps) change the results as
    // much as the configs do.
    const auto hash_file = [&](const std::filesystem::path& path) {
        if (!path.empty() && std::find(hashed_files.begin(), hashed_files.end(), path) == hashed_files.end())
            hashed_files.push_back(path);
    };
    const auto hash_object_files = [&](const Object& object) {
        if (object.shape == ShapeType::mesh) hash_file(object.mesh_file);
        if (object.shape == ShapeType::heightfield) hash_file(object.height_map_file);
    };
    for (const Scene& scene : experiment.scenes) {
        for (const Object& object : scene.objects) hash_object_files(object);
        for (const Population& population : scene.populations) {
            hash_object_files(population.prototype);
            if (const PopulationKind* kind = PopulationKindRegistry::instance().find(population.kind))
                for (const ParamSpec& spec : kind->params())
                    if (spec.type == ParamType::path) hash_file(population.params.path(spec.name));
        }
    }
    experiment.config_hash = hash_files(text, hashed_files);
    experiment.hashed_files = std::move(hashed_files);
    return experiment;
}

namespace {

// Case ids name files ("<id>.error.png"), and file names hold 255 bytes: a longer id keeps its
// first bytes (at a UTF-8 character boundary) and ends in a hash of the whole, so it stays
// readable and distinct.
constexpr size_t kMaxIdBytes = 200;

std::string bounded_id(const std::string& id) {
    if (id.size() <= kMaxIdBytes) return id;
    const std::string hash = fmt::format("_h{:016x}", fnv1a_64(id));
    size_t keep = kMaxIdBytes - hash.size();
    while (keep > 0 && (static_cast<unsigned char>(id[keep]) & 0xC0) == 0x80) --keep;
    return id.substr(0, keep) + hash;
}

}  // namespace

std::vector<Case> expand_cases(const Experiment& experiment, const TechniqueRegistry& registry) {
    std::vector<Case> cases;
    std::set<std::string> used_ids;
    for (size_t scene_index = 0; scene_index < experiment.scenes.size(); ++scene_index) {
        const Scene& scene = experiment.scenes[scene_index];
        for (const Resolution& resolution : experiment.resolutions) {
            for (const TechniqueEntry& entry : experiment.techniques) {
                const Technique* technique = registry.find(entry.name);
                if (!technique)
                    throw ConfigError(entry.where.file, entry.where.line,
                                      fmt::format("unknown technique '{}'", entry.name),
                                      "run `canopy list` to see every technique");
                const std::vector<std::string> keys = ordered_keys(entry);
                const std::vector<ParamSpec> specs = technique->params();

                // Odometer over the sweep: the first key varies slowest.
                std::vector<size_t> choice(keys.size(), 0);
                do {
                    std::map<std::string, ParamValue> given;
                    std::string id = fmt::format("{}_{}x{}_{}", scene.name, resolution.width, resolution.height,
                                                 entry.name);
                    for (size_t k = 0; k < keys.size(); ++k) {
                        const ParamValue& value = entry.sweep.at(keys[k])[choice[k]];
                        given[keys[k]] = value;
                        id += fmt::format("_{}-{}", keys[k], to_string(value));
                    }
                    id = bounded_id(file_name_safe(id));  // scene names are checked; values may hold anything
                    std::string unique_id = id;
                    for (int copy = 2; used_ids.count(unique_id); ++copy) unique_id = fmt::format("{}_{}", id, copy);
                    used_ids.insert(unique_id);

                    Case run_case;
                    run_case.scene_index = scene_index;
                    run_case.resolution = resolution;
                    run_case.technique = entry.name;
                    run_case.params = resolve_params(*technique, specs, given, entry.param_lines, entry.where);  // + conflicts
                    run_case.id = std::move(unique_id);
                    cases.push_back(std::move(run_case));
                } while (advance(choice, keys, entry));
            }
        }
    }
    return cases;
}

}  // namespace canopy
