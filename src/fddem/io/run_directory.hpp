// SPDX-License-Identifier: MIT
#pragma once
/// The run directory: created and checked writable before any work.

#include <filesystem>

namespace fddem {

/// Creates `directory` (and fields/, samples/). Throws InputError if it exists and is not
/// empty (unless `force`), or cannot be created or written. With `force` an existing run's
/// files are left in place until each is replaced.
void prepare_run_directory(const std::filesystem::path& directory, bool force);

} // namespace fddem
