#include "run/output_folder.hpp"

#include "core/error.hpp"
#include "report/atomic_file.hpp"
#include "report/json_record_reader.hpp"

#include <fmt/format.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>
#include <vector>

namespace canopy {

namespace fs = std::filesystem;

namespace {

// What every run writes beside its images (report.html: `canopy report`, or `run --report`).
constexpr std::array kReportFiles = {"results.json", "results.csv", "results.md", "results.gbench.json",
                                     "paper.md",     "paper.json",  "pareto.md",  "report.html"};

bool is_empty_folder(const fs::path& dir) { return fs::is_directory(dir) && fs::directory_iterator(dir) == fs::directory_iterator(); }

std::vector<fs::path> files_in(const fs::path& dir) {
    std::vector<fs::path> files;
    std::error_code error;
    if (!fs::is_directory(dir, error)) return files;
    for (const auto& entry : fs::directory_iterator(dir, error))
        if (entry.is_regular_file(error)) files.push_back(entry.path());
    return files;
}

std::string bulleted(const std::vector<std::string>& lines) {
    std::string out;
    for (const std::string& line : lines) out += "\n    " + line;
    return out;
}

}  // namespace

OutputFolderLock::OutputFolderLock(const fs::path& dir) {
    fs::create_directories(dir);
    fd_ = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd_ < 0) throw ConfigError(dir, 0, fmt::format("cannot open the output folder: {}", std::strerror(errno)));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        const int code = errno;
        ::close(fd_);
        fd_ = -1;
        if (code == EWOULDBLOCK)
            throw ConfigError(dir, 0, "another canopy run is writing to this folder",
                              "wait for it to finish (then run again to resume), or choose another --out");
        throw ConfigError(dir, 0, fmt::format("cannot lock the output folder: {}", std::strerror(code)));
    }
}

OutputFolderLock::~OutputFolderLock() {
    if (fd_ >= 0) ::close(fd_);  // releases the lock
}

fs::path output_file(const std::string& out, const std::string& file_name) {
    const fs::path given(out);
    std::error_code ec;
    const bool folder = fs::is_directory(given, ec) || (!out.empty() && out.back() == '/') || given.filename() == "." ||
                        given.filename() == "..";
    if (folder && fs::absolute(given).lexically_normal() == fs::absolute(given).root_path())
        throw ConfigError(given, 0, "is the filesystem's root folder: canopy writes no file there",
                          fmt::format("give a file (--out /tmp/{0}) or another folder (--out /tmp/ writes /tmp/{0})", file_name));
    const fs::path file = folder ? given / file_name : given;
    const fs::file_status status = fs::status(file, ec);
    if (fs::exists(status) && !fs::is_regular_file(status))
        throw ConfigError(file, 0, "is neither a file nor a folder (a device, a pipe or a socket): canopy would replace it",
                          "give a file or a folder with --out");
    // The nearest of the file's folders that exists must be a folder.
    for (fs::path parent = file.parent_path(); !parent.empty(); parent = parent.parent_path()) {
        const fs::file_status parent_status = fs::status(parent, ec);
        if (fs::is_directory(parent_status)) break;
        if (fs::exists(parent_status))
            throw ConfigError(parent, 0, fmt::format("is a file, not a folder: {} cannot be written", file.string()),
                              "give a path through folders with --out");
        if (parent == parent.parent_path()) break;
    }
    return file;
}

bool is_committed_results_folder(const fs::path& dir) {
    const fs::path full = fs::weakly_canonical(fs::absolute(dir));
    std::string previous;
    for (const fs::path& part : full) {
        const std::string name = part.string();
        if (previous == "results" && (name == "paper" || name == "baselines")) return true;
        previous = name;
    }
    return false;
}

OutputFolderPlan plan_output_folder(const fs::path& dir, const RunIdentity& identity, bool force, bool resume) {
    const std::string another = "write somewhere else with --out (e.g. results/runs/<name>)";
    if (is_committed_results_folder(dir) && !force)
        throw ConfigError(dir, 0, "this folder holds committed results (results/paper/ or results/baselines/); "
                                  "canopy does not write there unless told to",
                          another + ", or add --force to regenerate them (then review `git diff`)");
    if (fs::exists(dir) && !fs::is_directory(dir))
        throw ConfigError(dir, 0, "--out names a file, not a folder", another);

    OutputFolderPlan plan;
    if (!fs::exists(dir) || is_empty_folder(dir)) {
        if (resume)
            throw ConfigError(dir, 0, "nothing to resume: the folder holds no run", "drop --resume to start a new run");
        return plan;
    }
    // --force replaces a canopy run, and only what that run recorded as its own: a folder without
    // a readable results.json is someone else's, whatever its files are called.
    if (!fs::exists(dir / "results.json"))
        throw ConfigError(dir, 0, "the folder is not empty and holds no canopy run (no results.json); refusing to "
                                  "write into it, with or without --force",
                          another + ", or empty the folder yourself");
    RunRecord previous;
    try {
        previous = read_json_report(dir / "results.json");
    } catch (const std::runtime_error& e) {
        throw ConfigError(dir, 0,
                          fmt::format("the folder's results.json is not a canopy run canopy can read ({}); refusing to "
                                      "write into it, with or without --force",
                                      e.what()),
                          another + ", or remove the folder yourself");
    }
    if (force && !resume) {
        plan.replace = true;
        plan.previous = std::move(previous);
        return plan;
    }
    const std::vector<std::string> differences = identity_differences(previous.identity, identity);
    if (!differences.empty()) {
        // Options a rerun can match, or a commit, build, machine or config it cannot: resuming is
        // offered for the first alone.
        const bool options_alone = only_options_differ(previous.identity, identity);
        throw ConfigError(dir, 0,
                          fmt::format("the folder holds another run (experiment '{}'); refusing to overwrite or mix "
                                      "its results. It differs in:{}",
                                      previous.experiment, bulleted(differences)),
                          another + (options_alone ? "; or run with the options of the folder's run to resume it; or "
                                                     "add --force to replace it"
                                                   : "; or add --force to replace it (this build, machine or config "
                                                     "cannot continue it)"));
    }
    plan.previous = std::move(previous);
    return plan;
}

void remove_temporary_files(const fs::path& dir) {
    for (const fs::path& folder : {dir, dir / "images"})
        for (const fs::path& file : files_in(folder))
            if (is_temporary_file(file)) fs::remove(file);
}

std::vector<std::string> recorded_files(const RunRecord& run) {
    std::vector<std::string> files(kReportFiles.begin(), kReportFiles.end());
    // The config's copy, by a run that records its inputs (older runs wrote none: a user's own
    // experiment.toml beside one is kept).
    if (!run.inputs.empty()) files.push_back("experiment.toml");
    auto add = [&](const std::string& file) {
        if (!file.empty()) files.push_back(file);
    };
    for (const ReferenceRecord& r : run.references)
        for (const std::string* f : {&r.image_exr, &r.image_png, &r.visibility_exr, &r.pixel_visibility_exr}) add(*f);
    for (const CaseResult& c : run.cases)
        for (const std::string* f : {&c.image_exr, &c.image_png, &c.visibility_exr, &c.error_map_png, &c.flip_map_png})
            add(*f);
    return files;
}

size_t remove_run_outputs(const fs::path& dir, const RunRecord& run) {
    size_t removed = 0;
    for (const std::string& name : recorded_files(run)) {
        const fs::path file = dir / name;
        // A name that climbs out of the folder is not the run's to remove.
        if (fs::path(name).is_absolute() || name.find("..") != std::string::npos) continue;
        std::error_code error;
        if (fs::is_regular_file(file, error)) removed += fs::remove(file, error) ? 1 : 0;
    }
    for (const fs::path& folder : {dir, dir / "images"})
        for (const fs::path& file : files_in(folder))
            if (is_temporary_file(file)) removed += fs::remove(file) ? 1 : 0;
    return removed;
}

}  // namespace canopy
