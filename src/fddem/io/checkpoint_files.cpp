// SPDX-License-Identifier: MIT
#include "fddem/io/checkpoint_files.hpp"

#include "fddem/io/atomic_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <optional>
#include <string_view>
#include <system_error>

namespace fddem {
namespace {

constexpr std::string_view prefix = "checkpoint_";
constexpr std::string_view extension = ".ckpt";
/// What follows a checkpoint's file name in the name of one of its pieces.
constexpr std::string_view piece_marker = ".piece";

/// The step in a checkpoint's file name, none if the name is not one.
std::optional<long> step_of(const std::string& name)
{
    if (name.size() <= prefix.size() + extension.size() || !name.starts_with(prefix) ||
        !name.ends_with(extension)) {
        return std::nullopt;
    }
    const std::string_view digits(name.data() + prefix.size(),
                                  name.size() - prefix.size() - extension.size());
    if (!std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) {
        return std::nullopt;
    }
    long step = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), step);
    if (error != std::errc() || end != digits.data() + digits.size()) {
        return std::nullopt;
    }
    return step;
}

} // namespace

std::filesystem::path checkpoint_directory(const std::filesystem::path& run_directory)
{
    return run_directory / "checkpoints";
}

std::filesystem::path checkpoint_path(const std::filesystem::path& run_directory, long step)
{
    return checkpoint_directory(run_directory) /
           fmt::format("{}{:010d}{}", prefix, step, extension);
}

std::vector<CheckpointEntry> list_checkpoints(const std::filesystem::path& run_directory)
{
    std::vector<CheckpointEntry> entries;
    std::error_code error;
    const std::filesystem::path directory = checkpoint_directory(run_directory);
    if (!std::filesystem::is_directory(directory, error)) {
        return entries;
    }
    for (const auto& file : std::filesystem::directory_iterator(directory, error)) {
        if (const std::optional<long> step = step_of(file.path().filename().string());
            step && file.is_regular_file(error)) {
            entries.push_back({*step, file.path()});
        }
    }
    std::sort(entries.begin(), entries.end(),
              [](const CheckpointEntry& a, const CheckpointEntry& b) { return a.step > b.step; });
    return entries;
}

void prune_checkpoints(const std::filesystem::path& run_directory, int keep)
{
    const std::vector<CheckpointEntry> entries = list_checkpoints(run_directory);
    for (std::size_t k = static_cast<std::size_t>(std::max(keep, 1)); k < entries.size(); ++k) {
        std::error_code error;
        std::filesystem::remove(entries[k].path, error);
        if (error) {
            throw OutputError("cannot remove the old checkpoint " + entries[k].path.string() +
                              ": " + error.message());
        }
    }
    // The pieces of a run on several ranks (io/checkpoint.hpp) whose checkpoint is gone: those
    // just pruned. Those of a checkpoint set aside as damaged stay with it (it may be the user's
    // to mend).
    std::error_code error;
    std::vector<std::filesystem::path> orphans;
    for (const auto& file :
         std::filesystem::directory_iterator(checkpoint_directory(run_directory), error)) {
        const std::string name = file.path().filename().string();
        const std::size_t at = name.find(extension);
        if (at == std::string::npos || name.find(piece_marker) == std::string::npos ||
            name.find(".tmp.") != std::string::npos) {
            continue;
        }
        const std::filesystem::path master =
            file.path().parent_path() / name.substr(0, at + extension.size());
        std::filesystem::path damaged = master;
        damaged += ".damaged";
        if (!std::filesystem::exists(master, error) && !std::filesystem::exists(damaged, error)) {
            orphans.push_back(file.path());
        }
    }
    for (const auto& path : orphans) {
        std::filesystem::remove(path, error);
    }
}

std::filesystem::path set_checkpoint_aside(const std::filesystem::path& path)
{
    const std::string name = path.filename().string();
    std::filesystem::path aside = path;
    aside += ".damaged";
    std::error_code error;
    std::filesystem::rename(path, aside, error);
    if (error) {
        throw OutputError("cannot rename " + path.string() + ": " + error.message());
    }
    std::vector<std::filesystem::path> pieces;
    for (const auto& file : std::filesystem::directory_iterator(path.parent_path(), error)) {
        const std::string other = file.path().filename().string();
        if (other.starts_with(name + ".") && !other.starts_with(name + ".damaged") &&
            other.find(piece_marker) != std::string::npos &&
            other.find(".tmp.") == std::string::npos) {
            pieces.push_back(file.path());
        }
    }
    for (const auto& piece : pieces) {
        std::filesystem::path renamed = aside;
        renamed += piece.filename().string().substr(name.size());
        std::filesystem::rename(piece, renamed, error);
    }
    return aside;
}

void remove_stale_temporaries(const std::filesystem::path& directory)
{
    std::error_code error;
    if (!std::filesystem::is_directory(directory, error)) {
        return;
    }
    std::vector<std::filesystem::path> stale;
    for (const auto& file : std::filesystem::directory_iterator(directory, error)) {
        if (file.path().filename().string().find(".tmp.") != std::string::npos) {
            stale.push_back(file.path());
        }
    }
    for (const auto& path : stale) {
        std::filesystem::remove(path, error);
    }
}

} // namespace fddem
