// SPDX-License-Identifier: MIT
#pragma once
// SIGINT, SIGTERM and SIGHUP (a closed terminal, a batch system) end a run cleanly: the handler
// only records the signal; the time loop finishes its step, writes a checkpoint and ends (exit
// status exit_interrupted_base + the signal). The library's driver asks for the signal through
// the program's RunMonitor. SIGPIPE is ignored: a closed stdout or stderr (`fddem run … | head`)
// stops the printing (app/progress.cpp), not the run.

namespace fddem::app {

/// Installs the handlers (once, before anything is written: a signal during the set-up then
/// stops the run after its first step, with a checkpoint, instead of leaving temporaries). A
/// second signal of the same kind ends the process at once (the default action is restored
/// when the first one arrives).
void install_interrupt_handlers();

/// Writes to a closed pipe fail (EPIPE) instead of ending the process.
void ignore_broken_pipes();

/// The signal received (SIGINT, SIGTERM or SIGHUP), 0 if none.
[[nodiscard]] int pending_interrupt() noexcept;

} // namespace fddem::app
