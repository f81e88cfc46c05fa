// SPDX-License-Identifier: MIT
#pragma once
/// What the caller of a run sees of it while it goes, and how it asks it to stop. The library
/// never prints and never handles signals (STYLE.md §5): the `fddem` program's monitor draws
/// the progress line and reads its signal handlers; a test or a binding passes its own, or this
/// base class, which ignores everything and never stops the run.

#include <string>

namespace fddem {

class RunMonitor {
public:
    RunMonitor() = default;
    RunMonitor(const RunMonitor&) = default;
    RunMonitor& operator=(const RunMonitor&) = default;
    RunMonitor(RunMonitor&&) = default;
    RunMonitor& operator=(RunMonitor&&) = default;
    virtual ~RunMonitor() = default;

    /// A line for the user: derived values, warnings, how the run ended.
    virtual void message(const std::string& /*text*/) {}
    /// The time loop starts at this step and time (0 for a new run; a restarted run's
    /// checkpoint otherwise).
    virtual void loop_started(long /*step*/, double /*time*/) {}
    /// After every step.
    virtual void step_done(long /*step*/, double /*time*/, int /*outer_iterations*/) {}
    /// The time loop has ended (the closing outputs and the last message follow).
    virtual void loop_ended() {}
    /// Asked after every step that does not end the run: a signal number (SIGINT, SIGTERM, SIGHUP)
    /// stops the run after a checkpoint; 0 lets it go on.
    [[nodiscard]] virtual int pending_interrupt() { return 0; }
};

/// "SIGINT", "SIGTERM", "SIGHUP" or "a signal": how summary.json and the messages name an
/// interrupt.
[[nodiscard]] const char* signal_name(int signal) noexcept;

} // namespace fddem
