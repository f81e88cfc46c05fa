// SPDX-License-Identifier: MIT
#pragma once
/// Where a run keeps its checkpoints: RUN_DIR/checkpoints/checkpoint_<step>.ckpt (the step with
/// ten digits, so names sort as steps do), the newest `checkpoint.keep` of them; a run on N
/// ranks adds checkpoint_<step>.ckpt.<w>.piece<r> for r = 1 … N − 1 (io/checkpoint.hpp).

#include <filesystem>
#include <vector>

namespace fddem {

[[nodiscard]] std::filesystem::path
checkpoint_directory(const std::filesystem::path& run_directory);

/// RUN_DIR/checkpoints/checkpoint_<step>.ckpt
[[nodiscard]] std::filesystem::path checkpoint_path(const std::filesystem::path& run_directory,
                                                    long step);

struct CheckpointEntry {
    long step = 0;
    std::filesystem::path path;
};

/// The checkpoint files of a run, newest (largest step) first. Other files (temporaries of a
/// killed run, checkpoints set aside as damaged) are not listed. None if there is no directory.
[[nodiscard]] std::vector<CheckpointEntry>
list_checkpoints(const std::filesystem::path& run_directory);

/// Removes all but the newest `keep` (≥ 1) checkpoints, and the pieces (<name>.<w>.piece<r>,
/// io/checkpoint.hpp) of checkpoints that are not there (neither as such nor set aside as
/// damaged). Throws OutputError.
void prune_checkpoints(const std::filesystem::path& run_directory, int keep);

/// Renames a checkpoint that cannot be used to "<name>.damaged", and its pieces
/// ("<name>.<w>.piece<r>") to "<name>.damaged.<w>.piece<r>", so that a new write of the same
/// step neither reads nor removes them; returns the new name of the checkpoint's file. Throws
/// OutputError if the file cannot be renamed.
std::filesystem::path set_checkpoint_aside(const std::filesystem::path& path);

/// Removes the temporary files a process killed while writing left in `directory`
/// (io/atomic_file names them <name>.tmp.<pid>).
void remove_stale_temporaries(const std::filesystem::path& directory);

} // namespace fddem
