// SPDX-License-Identifier: MIT
// A restarted run: restore the newest usable checkpoint, check that the outputs hold what it
// records (all before anything is written), cut the outputs back to its step, then continue
// with the shared time loop (driver.cpp).

#include "fddem/core/errors.hpp"
#include "fddem/io/atomic_file.hpp"
#include "fddem/io/case_changes.hpp"
#include "fddem/io/checkpoint.hpp"
#include "fddem/io/checkpoint_files.hpp"
#include "fddem/run/driver.hpp"
#include "fddem/run/field_frames.hpp"
#include "fddem/run/memory_estimate.hpp"
#include "fddem/run/rank_reasons.hpp"
#include "fddem/run/run_messages.hpp"

#include <fmt/format.h>

#include <optional>
#include <utility>
#include <vector>

namespace fddem {
namespace {

namespace fs = std::filesystem;

struct Damaged {
    fs::path path;
    std::string reason;
};

/// Why the case ends where the checkpoint is, and the --set that runs it further, for the
/// "nothing to do" message.
std::pair<std::string, std::string> end_reason(const CaseConfig& config, const Clock& clock,
                                               std::optional<double> at_rest_since)
{
    if (clock.step >= config.time.max_steps) {
        return {fmt::format("time.max_steps = {}", config.time.max_steps), "time.max_steps=…"};
    }
    if (config.time.end && clock.time >= *config.time.end - 0.5 * clock.dt) {
        return {fmt::format("time.end = {:g} s", *config.time.end), "time.end=…"};
    }
    // A settled or steady run stays so: only a later time.min_end lets it go on.
    if (config.time.rest_speed && at_rest_since) {
        return {fmt::format("every free body has been at rest since t = {:g} s (time.rest_speed)",
                            *at_rest_since),
                "time.min_end=…"};
    }
    return {"the flow is steady (time.steady_tolerance)", "time.min_end=…"};
}

} // namespace

template <int Dim>
RunResult Driver<Dim>::resume(bool rewrite_case)
{
    std::vector<Damaged> damaged;
    std::optional<CheckpointEntry> used;
    std::string checkpoint_case;
    // Every rank reads the checkpoint's file and the pieces its block overlaps
    // (io/checkpoint.hpp); a checkpoint one rank cannot use is set aside by all of them, with
    // that rank's reason.
    for (const CheckpointEntry& entry : list_checkpoints(directory_)) {
        std::optional<std::string> reason;
        try {
            const CheckpointFile file(entry.path);
            file.restore(sim_, record_);
            checkpoint_case = file.header().case_text;
        } catch (const CheckpointError& e) {
            reason = e.what();
        }
        // Every rank takes the same checkpoint: the first that none of them refused.
        reason = first_reason(ranks_, reason, "read on rank");
        if (!reason) {
            used = entry;
            break;
        }
        if (!is_writer()) {
            continue;
        }
        damaged.push_back({entry.path, *reason});
    }
    if (ranks_.size() > 1 && !is_writer()) {
        if (!used) {
            // No usable checkpoint: rank 0 says why below; every rank ends with an input error
            // (app/error_agreement.hpp).
            throw InputError(checkpoint_directory(directory_).string(), 0, "",
                             "no usable checkpoint");
        }
        // The other ranks step along; rank 0 checks and prepares the run directory. A rank-0
        // input error below (outputs_.check: a CSV history missing or cut) is not agreed: rank
        // 0 says it and, after app/main.cpp's wait, ends every rank by MPI_Abort.
        return sim_.is_finished(record_.last) ? RunResult{} : step_to_end();
    }
    if (!used) {
        std::string reasons;
        for (const Damaged& file : damaged) {
            reasons += fmt::format("; {} {}", file.path.filename().string(), file.reason);
        }
        throw InputError(checkpoint_directory(directory_).string(), 0, "",
                         damaged.empty() ? std::string("no checkpoint to restart from")
                                         : "no usable checkpoint" + reasons);
    }
    const Clock& clock = sim_.clock();
    if (sim_.is_finished(record_.last)) {
        const auto [reason, extend] = end_reason(config_, clock, sim_.at_rest_since());
        monitor_.message(fmt::format(
            "fddem: {} is complete: step {}, t = {:g} s is the end of its case ({}); nothing to "
            "do. To run further: fddem run --restart {} --set {}",
            directory_.string(), clock.step, clock.time, reason, directory_.string(), extend));
        return {RunResult::Outcome::completed, 0};
    }
    outputs_.check(record_);
    // Frames the user deleted stay out of the .pvd collections (which must list only files
    // that exist); later frames are numbered on from the last one listed.
    for (auto* frames : {&record_.field_frames, &record_.particle_frames}) {
        for (const std::string& file : drop_missing_frames(directory_, *frames)) {
            monitor_.message("fddem: warning: " + file +
                             ", a frame of the checkpoint, is missing; left out of its .pvd");
        }
    }

    // Nothing was written so far; from here on the run directory is brought back to the step.
    for (const Damaged& file : damaged) {
        const fs::path aside = set_checkpoint_aside(file.path); // with its pieces
        monitor_.message(fmt::format("fddem: checkpoint {} {}; set aside as {}", file.path.string(),
                                     file.reason, aside.filename().string()));
    }
    report_start(config_, monitor_, ranks_.size(), ranks_on_node_);
    monitor_.message(fmt::format("fddem: restarting {} from step {} (t = {:g} s), {}",
                                 directory_.string(), clock.step, clock.time,
                                 used->path.filename().string()));
    for (const std::string& change : case_changes(checkpoint_case, config_.as_run)) {
        if (!change.starts_with("derived.")) {
            monitor_.message("fddem: changed since the checkpoint: " + change);
        }
    }
    if (rewrite_case) {
        write_file_atomically(directory_ / "case.toml", config_.as_run);
    }
    for (const char* folder : {"", "fields", "particles", "samples", "checkpoints"}) {
        remove_stale_temporaries(directory_ / folder);
    }
    outputs_.continue_from(record_);
    ++record_.restarts;
    last_checkpoint_ = used->path;
    report_derived_values(config_, monitor_);
    return step_to_end();
}

template RunResult Driver<2>::resume(bool);
template RunResult Driver<3>::resume(bool);

} // namespace fddem
