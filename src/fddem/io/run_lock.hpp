// SPDX-License-Identifier: MIT
#pragma once
/// One fddem process at a time in a run directory: an advisory lock (flock) on DIR/.fddem.lock,
/// which holds the holder's pid. Two processes writing one run directory (a run and a
/// --restart of it, two restarts) would interleave solver.csv and overwrite each other's
/// checkpoints; the second one stops before any work instead.

#include <filesystem>
#include <string_view>

namespace fddem {

/// The lock file's name in a run directory; it stays there, empty of meaning once unlocked.
inline constexpr std::string_view run_lock_name = ".fddem.lock";

class RunLock {
public:
    /// Takes the lock on `directory`, creating the directory if need be. Throws InputError if
    /// another process holds it (naming its pid), or if the directory cannot be created or
    /// written. Never waits.
    explicit RunLock(const std::filesystem::path& directory);
    /// Releases the lock. The kernel releases it too when the process ends in any way (exit,
    /// a signal, kill -9): a flock belongs to the open file, which dies with the process.
    ~RunLock();
    RunLock(const RunLock&) = delete;
    RunLock& operator=(const RunLock&) = delete;
    RunLock(RunLock&&) = delete;
    RunLock& operator=(RunLock&&) = delete;

private:
    int descriptor_ = -1;
};

/// Throws InputError as RunLock would if another process holds the lock on `directory` (which
/// must exist), without keeping it: a first check, before a restart reads the directory. Creates
/// nothing: a directory without the lock file was never locked.
void check_unlocked(const std::filesystem::path& directory);

} // namespace fddem
