// SPDX-License-Identifier: MIT
#include "fddem/io/run_directory.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/io/atomic_file.hpp"

#include <algorithm>
#include <cstdio>
#include <system_error>
#include <unistd.h>

namespace fddem {

void prepare_run_directory(const std::filesystem::path& directory, bool force)
{
    namespace fs = std::filesystem;
    std::error_code error;
    const std::string name = directory.string();
    if (fs::exists(directory, error)) {
        if (!fs::is_directory(directory, error)) {
            throw InputError(name, 0, "", "the run directory exists and is not a directory");
        }
        if (!force && !fs::is_empty(directory, error)) {
            throw InputError(name, 0, "",
                             "the run directory exists and is not empty; use --force to "
                             "overwrite it or -o to choose another");
        }
    }
    for (const fs::path& d : {directory, directory / "fields", directory / "samples"}) {
        fs::create_directories(d, error);
        if (error) {
            throw InputError(d.string(), 0, "",
                             "cannot create the run directory: " + error.message());
        }
    }
    if (::access(directory.c_str(), W_OK) != 0) {
        throw InputError(name, 0, "", "the run directory is not writable");
    }
    // Creating a file proves writability where access() is not enough (read-only mounts).
    const fs::path probe = directory / ".fddem-write-test";
    std::FILE* file = std::fopen(probe.c_str(), "wb");
    if (file == nullptr) {
        throw InputError(name, 0, "", "the run directory is not writable");
    }
    std::fclose(file);
    fs::remove(probe, error);
}

int remove_unlisted_files(const std::filesystem::path& directory, const std::string& folder,
                          const std::string& extension,
                          const std::vector<std::pair<double, std::string>>& listed)
{
    namespace fs = std::filesystem;
    std::error_code error;
    if (!fs::is_directory(directory / folder, error)) {
        return 0;
    }
    std::vector<fs::path> unlisted;
    for (const auto& file : fs::directory_iterator(directory / folder, error)) {
        const std::string relative = folder + "/" + file.path().filename().string();
        const bool is_listed = std::any_of(listed.begin(), listed.end(), [&](const auto& entry) {
            return entry.second == relative;
        });
        if (relative.ends_with(extension) && !is_listed) {
            unlisted.push_back(file.path());
        }
    }
    for (const fs::path& path : unlisted) {
        fs::remove(path, error);
        if (error) {
            throw OutputError("cannot remove " + path.string() + ": " + error.message());
        }
    }
    return static_cast<int>(unlisted.size());
}

} // namespace fddem
