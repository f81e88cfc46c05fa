// SPDX-License-Identifier: MIT
#include "fddem/run/run_case.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/io/case_reader.hpp"
#include "fddem/io/checkpoint_files.hpp"
#include "fddem/io/run_directory.hpp"
#include "fddem/io/run_lock.hpp"
#include "fddem/run/memory_estimate.hpp"
#include "fddem/run/rank_reasons.hpp"

#include <fmt/format.h>

#include <optional>
#include <system_error>

namespace fddem {

namespace fs = std::filesystem;

namespace {

/// `go(driver)` with the driver of the case's dimension.
template <class Go>
RunResult drive(const CaseConfig& config, const fs::path& directory, RunMonitor& monitor,
                const Communicator& ranks, const Go& go)
{
    // Before anything is allocated: a grid that does not fit stops here (exit status 2).
    // Each rank checks its own machine (their ranks and memory may differ); all stop alike.
    // (A layout that cannot be made fails alike on every rank, with its own key.)
    std::optional<std::string> failure;
    std::string key = "domain.cells";
    try {
        check_run_memory(config, run_memory_limit(config), ranks.size(),
                         ranks.ranks_on_this_node());
    } catch (const InputError& e) {
        failure = e.what();
        key = e.key();
    }
    if (const auto said = first_reason(ranks, failure, "on the machine of rank")) {
        throw InputError(config.source_file, 0, key, *said);
    }
    if (config.domain.dimension == 2) {
        Driver<2> driver(config, directory, monitor, ranks);
        return go(driver);
    }
    Driver<3> driver(config, directory, monitor, ranks);
    return go(driver);
}

} // namespace

RunResult run_case(const CaseConfig& config, const fs::path& directory, RunMonitor& monitor,
                   bool overwrite, const Communicator& ranks)
{
    // Rank 0 alone checks (and then writes) the directory: its lock is tried by one process.
    // Every rank ends alike if it fails (agree_on_input_error).
    agree_on_input_error(ranks, ranks.rank() == 0, [&] {
        std::error_code error;
        if (fs::is_directory(directory, error)) {
            check_unlocked(directory); // before "not empty": the holder of the lock is the news
        }
        check_run_directory(directory, overwrite);
    });
    return drive(config, directory, monitor, ranks, [&](auto& driver) {
        std::optional<RunLock> lock;
        agree_on_input_error(ranks, ranks.rank() == 0, [&] { lock.emplace(directory); });
        return driver.start(overwrite);
    });
}

CaseConfig read_restart_case(const fs::path& directory, const std::vector<std::string>& overrides,
                             bool check_lock)
{
    std::error_code error;
    if (!fs::is_directory(directory, error)) {
        throw InputError(directory.string(), 0, "",
                         fs::exists(directory, error) ? "cannot restart: not a run directory"
                                                      : "cannot restart: no such run directory");
    }
    const fs::path case_file = directory / "case.toml";
    if (!fs::exists(case_file, error)) {
        throw InputError(case_file.string(), 0, "",
                         "cannot restart: missing (not an fddem run directory?)");
    }
    if (check_lock) {
        check_unlocked(directory);
    }
    CaseConfig config = read_case(case_file.string(), overrides);
    if (list_checkpoints(directory).empty()) {
        throw InputError(checkpoint_directory(directory).string(), 0, "",
                         "cannot restart: no checkpoint (a run writes one every "
                         "checkpoint.step_interval steps, at its end and when interrupted)");
    }
    return config;
}

RunResult restart_run(const CaseConfig& config, const fs::path& directory, RunMonitor& monitor,
                      bool rewrite_case, const Communicator& ranks)
{
    std::optional<RunLock> lock;
    agree_on_input_error(ranks, ranks.rank() == 0, [&] {
        lock.emplace(directory);
        check_run_directory_writable(directory);
    });
    return drive(config, directory, monitor, ranks,
                 [rewrite_case](auto& driver) { return driver.resume(rewrite_case); });
}

} // namespace fddem
