// SPDX-License-Identifier: MIT
#pragma once
/// The run directory: created and checked writable before any work.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace fddem {

/// Creates `directory` (and fields/, samples/). Throws InputError if it exists and is not
/// empty (unless `force`), or cannot be created or written. With `force` an existing run's
/// files are left in place until each is replaced.
void prepare_run_directory(const std::filesystem::path& directory, bool force);

/// Removes the files of `directory`/`folder` whose names end in `extension` and that are not
/// among `listed` (paths relative to `directory`, as in a .pvd): the frames a run wrote after
/// the checkpoint it is restarted from. Returns how many were removed. Throws OutputError.
int remove_unlisted_files(const std::filesystem::path& directory, const std::string& folder,
                          const std::string& extension,
                          const std::vector<std::pair<double, std::string>>& listed);

} // namespace fddem
