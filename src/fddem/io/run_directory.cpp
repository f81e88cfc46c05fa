// SPDX-License-Identifier: MIT
#include "fddem/io/run_directory.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/io/atomic_file.hpp"
#include "fddem/io/run_lock.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <regex>
#include <system_error>

namespace fddem {
namespace {

namespace fs = std::filesystem;

/// The folders of a run directory that fddem writes into.
constexpr std::array<const char*, 4> run_folders{"fields", "particles", "samples", "checkpoints"};

/// The file that proves a directory writable (created and removed at once).
constexpr const char* write_probe = ".fddem-write-test";

/// The folders of a split run's frame pieces: fields/fields_NNNNNN/ and particles/particles_NNNNNN/
/// (run/field_frames.hpp).
bool is_piece_folder(const std::string& folder, const std::string& name)
{
    static const std::regex frame("[0-9]+");
    return name.starts_with(folder + "_") &&
           std::regex_match(name.substr(folder.size() + 1), frame);
}

/// The files of `directory`, of its run folders and of their frames' piece folders, as paths
/// relative to it ("" folder: the directory itself).
std::vector<std::string> files_of_run_directory(const fs::path& directory)
{
    std::vector<std::string> files;
    std::error_code error;
    const auto add = [&](const fs::path& at, const std::string& prefix) {
        for (const auto& entry : fs::directory_iterator(at, error)) {
            if (!entry.is_directory(error)) {
                files.push_back(prefix + entry.path().filename().string());
            }
        }
    };
    add(directory, "");
    for (const char* folder : run_folders) {
        if (!fs::is_directory(directory / folder, error)) {
            continue;
        }
        add(directory / folder, std::string(folder) + "/");
        for (const auto& entry : fs::directory_iterator(directory / folder, error)) {
            const std::string name = entry.path().filename().string();
            if (entry.is_directory(error) && is_piece_folder(folder, name)) {
                add(entry.path(), std::string(folder) + "/" + name + "/");
            }
        }
    }
    return files;
}

/// Removes the piece folders of `directory`/`folder` that are empty (their files removed).
void remove_empty_piece_folders(const fs::path& directory, const std::string& folder)
{
    std::error_code error;
    std::vector<fs::path> empty;
    for (const auto& entry : fs::directory_iterator(directory / folder, error)) {
        if (entry.is_directory(error) &&
            is_piece_folder(folder, entry.path().filename().string()) &&
            fs::is_empty(entry.path(), error)) {
            empty.push_back(entry.path());
        }
    }
    for (const fs::path& path : empty) {
        fs::remove(path, error);
    }
}

/// A temporary of an output (`case.toml.tmp.PID`), left by a process killed while it wrote.
bool is_stale_temporary(const std::string& relative)
{
    return is_run_output(relative) && relative.find(".tmp.") != std::string::npos;
}

/// Left by a run that was stopped before it had written anything of use: the lock file, a
/// temporary of an output (`case.toml.tmp.PID`: kill -9 while it was written), an empty run
/// folder.
bool is_leftover(const fs::path& directory, const fs::directory_entry& entry)
{
    std::error_code error;
    const std::string name = entry.path().filename().string();
    if (entry.is_directory(error)) {
        return std::find(run_folders.begin(), run_folders.end(), name) != run_folders.end() &&
               fs::is_empty(entry.path(), error);
    }
    return name == run_lock_name || is_stale_temporary(name) ||
           entry.path() == directory / write_probe;
}

/// Creating a file proves writability where access() is not enough (read-only mounts).
void check_writable(const fs::path& directory)
{
    const fs::path probe = directory / write_probe;
    std::FILE* file = std::fopen(probe.c_str(), "wb");
    if (file == nullptr) {
        throw InputError(directory.string(), 0, "", "the run directory is not writable");
    }
    std::fclose(file);
    std::error_code error;
    fs::remove(probe, error);
}

} // namespace

bool is_run_output(const std::string& relative)
{
    static const std::regex outputs(
        R"((case\.toml|solver\.csv|particles\.csv|summary\.json|fields\.pvd|particles\.pvd|)"
        R"(fields/fields_[0-9]+\.p?vtr|particles/particles_[0-9]+\.p?vtp|)"
        R"(fields/fields_[0-9]+/fields_[0-9]+_[0-9]+\.vtr|)"
        R"(particles/particles_[0-9]+/particles_[0-9]+_[0-9]+\.vtp|samples/[^/]+\.csv|)"
        R"(checkpoints/checkpoint_[0-9]+\.ckpt(\.damaged)?(\.[0-9]+\.piece[0-9]+)?|\.fddem-write-test)(\.tmp\.[0-9]+)?)");
    return std::regex_match(relative, outputs);
}

void check_run_directory(const fs::path& directory, bool force)
{
    std::error_code error;
    const std::string name = directory.string();
    if (!fs::exists(directory, error)) {
        return;
    }
    if (!fs::is_directory(directory, error)) {
        throw InputError(name, 0, "", "the run directory exists and is not a directory");
    }
    if (force) {
        return;
    }
    for (const auto& entry : fs::directory_iterator(directory, error)) {
        if (!is_leftover(directory, entry)) {
            throw InputError(name, 0, "",
                             "the run directory exists and is not empty; use --force to "
                             "overwrite it or -o to choose another");
        }
    }
}

namespace {

/// Removes the files of `directory` and its run folders for which `is_removed(relative path)`.
template <class Predicate>
int remove_run_files(const fs::path& directory, const Predicate& is_removed)
{
    int removed = 0;
    for (const std::string& file : files_of_run_directory(directory)) {
        if (!is_removed(file)) {
            continue;
        }
        std::error_code error;
        fs::remove(directory / file, error);
        if (error) {
            throw InputError(directory.string(), 0, "",
                             "cannot remove " + file + " of the old run: " + error.message());
        }
        ++removed;
    }
    return removed;
}

} // namespace

int remove_run_outputs(const fs::path& directory)
{
    const int removed = remove_run_files(directory, is_run_output);
    for (const char* folder : {"fields", "particles"}) {
        remove_empty_piece_folders(directory, folder);
    }
    return removed;
}

void prepare_run_directory(const fs::path& directory, bool force)
{
    check_run_directory(directory, force);
    check_writable(directory);
    if (force) {
        remove_run_outputs(directory);
    } else {
        remove_run_files(directory, is_stale_temporary); // of a run stopped at its start
    }
    std::error_code error;
    for (const fs::path& d : {directory / "fields", directory / "samples"}) {
        fs::create_directories(d, error);
        if (error) {
            throw InputError(d.string(), 0, "",
                             "cannot create the run directory: " + error.message());
        }
    }
}

void check_run_directory_writable(const fs::path& directory)
{
    check_writable(directory);
    std::error_code error;
    for (const char* folder : run_folders) {
        if (fs::is_directory(directory / folder, error)) {
            check_writable(directory / folder);
        }
    }
}

int remove_unlisted_files(const fs::path& directory, const std::string& folder,
                          const std::vector<std::string>& extensions,
                          const std::vector<std::pair<double, std::string>>& listed)
{
    std::error_code error;
    if (!fs::is_directory(directory / folder, error)) {
        return 0;
    }
    const auto is_listed = [&](const std::string& relative) {
        return std::any_of(listed.begin(), listed.end(),
                           [&](const auto& entry) { return entry.second == relative; });
    };
    std::vector<fs::path> unlisted;
    for (const auto& file : fs::directory_iterator(directory / folder, error)) {
        const std::string name = file.path().filename().string();
        const std::string relative = folder + "/" + name;
        if (file.is_directory(error)) {
            // A split run's piece folder (fields/fields_NNNNNN/): unlisted with its master.
            const bool has_listed_master = std::any_of(
                extensions.begin(), extensions.end(),
                [&](const std::string& extension) { return is_listed(relative + extension); });
            if (is_piece_folder(folder, name) && !has_listed_master) {
                unlisted.push_back(file.path());
            }
            continue;
        }
        const bool is_frame =
            std::any_of(extensions.begin(), extensions.end(),
                        [&](const std::string& extension) { return name.ends_with(extension); });
        if (is_frame && !is_listed(relative)) {
            unlisted.push_back(file.path());
        }
    }
    for (const fs::path& path : unlisted) {
        fs::remove_all(path, error);
        if (error) {
            throw OutputError("cannot remove " + path.string() + ": " + error.message());
        }
    }
    return static_cast<int>(unlisted.size());
}

} // namespace fddem
