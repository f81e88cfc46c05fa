// SPDX-License-Identifier: MIT
// `fddem run`: read and check the case, build the simulation, prepare the run directory (in that
// order, so bad input writes nothing), then step to the end writing the outputs (app/run.cpp).
// With --restart, the run directory's case and newest usable checkpoint (app/run_restart.cpp).

#include "fddem/core/errors.hpp"
#include "fddem/io/case_reader.hpp"
#include "fddem/io/checkpoint_files.hpp"

#include <filesystem>
#include <system_error>

#include "commands.hpp"
#include "run.hpp"

namespace fddem::app {
namespace {

namespace fs = std::filesystem;

fs::path default_run_directory(const RunOptions& options, const CaseConfig& config)
{
    if (!options.output_directory.empty()) {
        return options.output_directory;
    }
    if (!config.output.directory.empty()) {
        return config.output.directory;
    }
    const fs::path file(options.case_file);
    // cases/<…>/<name>/case.toml runs into runs/<name>.
    const std::string stem = file.stem() == "case" && file.has_parent_path()
                                 ? fs::absolute(file).parent_path().filename().string()
                                 : file.stem().string();
    return fs::path("runs") / stem;
}

int restart_command(const RunOptions& options)
{
    const fs::path directory = options.restart_directory;
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
    const CaseConfig config = read_case(case_file.string(), options.overrides);
    if (list_checkpoints(directory).empty()) {
        throw InputError(checkpoint_directory(directory).string(), 0, "",
                         "cannot restart: no checkpoint (a run writes one every "
                         "checkpoint.step_interval steps, at its end and when interrupted)");
    }
    const bool has_overrides = !options.overrides.empty();
    if (config.domain.dimension == 2) {
        Run<2> run(config, directory, options);
        return run.resume(has_overrides);
    }
    Run<3> run(config, directory, options);
    return run.resume(has_overrides);
}

} // namespace

int run_command(const RunOptions& options)
{
    if (!options.restart_directory.empty()) {
        return restart_command(options);
    }
    const CaseConfig config = read_case(options.case_file, options.overrides);
    const fs::path directory = default_run_directory(options, config);
    if (config.domain.dimension == 2) {
        Run<2> run(config, directory, options);
        return run.start(options.force);
    }
    Run<3> run(config, directory, options);
    return run.start(options.force);
}

} // namespace fddem::app
