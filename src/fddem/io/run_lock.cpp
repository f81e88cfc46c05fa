// SPDX-License-Identifier: MIT
#include "fddem/io/run_lock.hpp"

#include "fddem/core/errors.hpp"

#include <array>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <string>
#include <sys/file.h>
#include <system_error>
#include <unistd.h>

namespace fddem {
namespace {

/// The pid the holder wrote into the lock file, "unknown" if it has not yet.
std::string holder_pid(int descriptor)
{
    std::array<char, 32> text{};
    const ssize_t n = ::pread(descriptor, text.data(), text.size() - 1, 0);
    return n > 0 ? std::string(text.data(), static_cast<std::size_t>(n)) : "unknown";
}

} // namespace

RunLock::RunLock(const std::filesystem::path& directory)
{
    const std::string name = directory.string();
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error) {
        throw InputError(name, 0, "", "cannot create the run directory: " + error.message());
    }
    const std::filesystem::path path = directory / run_lock_name;
    descriptor_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (descriptor_ < 0) {
        throw InputError(name, 0, "",
                         "the run directory is not writable (cannot create " +
                             std::string(run_lock_name) + ": " + std::strerror(errno) + ")");
    }
    if (::flock(descriptor_, LOCK_EX | LOCK_NB) != 0) {
        const std::string pid = holder_pid(descriptor_);
        ::close(descriptor_);
        throw InputError(name, 0, "",
                         "the run directory is in use by another fddem process (pid " + pid +
                             "); wait for it to end, or give another run directory with -o");
    }
    const std::string pid = std::to_string(::getpid());
    if (::ftruncate(descriptor_, 0) != 0 ||
        ::pwrite(descriptor_, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
        ::close(descriptor_);
        throw InputError(name, 0, "",
                         "the run directory is not writable (cannot write " +
                             std::string(run_lock_name) + ": " + std::strerror(errno) + ")");
    }
}

RunLock::~RunLock()
{
    // Emptied first, so that a pid read later is never a stale one.
    (void)::ftruncate(descriptor_, 0);
    ::close(descriptor_);
}

void check_unlocked(const std::filesystem::path& directory)
{
    std::error_code error;
    if (!std::filesystem::exists(directory / run_lock_name, error)) {
        return; // no process has locked it (a holder creates the file): nothing to write
    }
    const RunLock probe(directory);
}

} // namespace fddem
