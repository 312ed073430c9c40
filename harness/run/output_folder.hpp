// Where a run may write. A run never writes over another run's results (that would mix two
// experiments' files and leave stale images), and never into committed results (results/paper/,
// results/baselines/) unless asked to with --force. A folder that holds a run of the same
// identity (run_identity.hpp) is continued: its finished cases are kept.
#pragma once

#include "run/case_result.hpp"
#include "run/run_identity.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace canopy {

struct OutputFolderPlan {
    std::optional<RunRecord> previous;  // a run to continue, or none: start afresh
    bool replace = false;               // --force over another run: remove `previous`'s recorded files first
};

// Decides how a run with `identity` may use `dir`, before anything is written. Throws ConfigError
// naming the folder (exit code 2) with what to do instead when the folder holds something else,
// is committed results without `force`, or `resume` finds nothing to continue.
//   empty or new folder   -> start afresh (with `resume`: error, nothing to continue)
//   same identity         -> continue it (with or without `resume`)
//   another canopy run    -> error; with `force` (and no `resume`): replace it (`previous` is
//                            the run replaced, whose recorded files remove_run_outputs removes)
//   no canopy run         -> error, also with `force`: canopy removes only what it recorded
OutputFolderPlan plan_output_folder(const std::filesystem::path& dir, const RunIdentity& identity, bool force,
                                    bool resume);

// While it lives, no other canopy process can hold the same folder (flock on the folder itself:
// no lock file is left behind, and the lock goes with the process, also when it is killed).
// Creates the folder. Throws ConfigError (exit code 2) when another run holds it.
class OutputFolderLock {
public:
    explicit OutputFolderLock(const std::filesystem::path& dir);
    ~OutputFolderLock();
    OutputFolderLock(const OutputFolderLock&) = delete;
    OutputFolderLock& operator=(const OutputFolderLock&) = delete;

private:
    int fd_ = -1;
};

// The file a command's --out names (`canopy report`'s page, `canopy compare`'s table), checked
// before anything is written: a folder (one that exists, or a path ending in '/') gets
// `file_name` inside it; anything else is the file itself. Throws ConfigError (exit code 2) for
// the filesystem's root folder, for something that is neither a file nor a folder (a device, a
// pipe) and for a path through a file. Creates nothing: the caller creates the file's folder.
std::filesystem::path output_file(const std::string& out, const std::string& file_name);

// Whether `dir` is, or is under, a results/paper or results/baselines folder.
bool is_committed_results_folder(const std::filesystem::path& dir);

// The files `run` recorded as its own, relative to its folder: its reports (results.json, .csv, .md,
// .gbench.json, paper.md, paper.json, pareto.md, report.html), the copy of its config
// (experiment.toml) and every image its cases and references name.
std::vector<std::string> recorded_files(const RunRecord& run);
// Removes the files `run` (the folder's results.json) recorded as its own and canopy's temporary
// files, nothing else: a user's file is kept whatever it is called. Returns how many it removed.
size_t remove_run_outputs(const std::filesystem::path& dir, const RunRecord& run);
// Removes the temporary files a killed run left behind (atomic_file.hpp's names).
void remove_temporary_files(const std::filesystem::path& dir);

}  // namespace canopy
