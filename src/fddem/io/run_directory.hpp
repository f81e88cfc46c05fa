// SPDX-License-Identifier: MIT
#pragma once
/// The run directory: checked before any work, created, cleared of an old run's outputs with
/// --force.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace fddem {

/// Whether `relative` (a path relative to a run directory) names a file fddem writes there:
/// case.toml, the histories, summary.json, the .pvd collections and their frames (a split
/// run's master files and their pieces too), the line samples, the checkpoints (and their
/// `*.damaged`), and a temporary of any of them.
[[nodiscard]] bool is_run_output(const std::string& relative);

/// Before any work, writing nothing: throws InputError if `directory` exists and is not a
/// directory, or (unless `force`) holds anything but what a run stopped at its very start leaves
/// (the lock file, temporaries of outputs, empty run folders).
void check_run_directory(const std::filesystem::path& directory, bool force);

/// Removes the files of an old run from `directory` (is_run_output; nothing else of the
/// user's), for `--force`. Returns how many. Throws InputError if one cannot be removed.
int remove_run_outputs(const std::filesystem::path& directory);

/// A new run's directory: check_run_directory, then writable (InputError if not), the old run's
/// outputs removed (with `force`), fields/ and samples/ created.
void prepare_run_directory(const std::filesystem::path& directory, bool force);

/// A restart's directory: throws InputError unless it and its run folders are writable.
void check_run_directory_writable(const std::filesystem::path& directory);

/// Removes the files of `directory`/`folder` whose names end in one of `extensions` and that
/// are not among `listed` (paths relative to `directory`, as in a .pvd), and the piece folders
/// of a split run's frames (`folder`/`folder`_NNNNNN/, run/field_frames.hpp) whose master file
/// is not listed: the frames a run wrote after the checkpoint it is restarted from. Returns how
/// many files and folders were removed. Throws OutputError.
int remove_unlisted_files(const std::filesystem::path& directory, const std::string& folder,
                          const std::vector<std::string>& extensions,
                          const std::vector<std::pair<double, std::string>>& listed);

} // namespace fddem
