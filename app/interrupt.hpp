// SPDX-License-Identifier: MIT
#pragma once
// SIGINT and SIGTERM end a run cleanly: the handler only records the signal; the time loop
// finishes its step, writes a checkpoint and ends (exit status exit_interrupted_base + the
// signal). The library's driver asks for the signal through the program's RunMonitor.

namespace fddem::app {

/// Installs the handlers (once, before the time loop). A second signal of the same kind ends
/// the process at once (the default action is restored when the first one arrives).
void install_interrupt_handlers();

/// The signal received (SIGINT or SIGTERM), 0 if none.
[[nodiscard]] int pending_interrupt() noexcept;

} // namespace fddem::app
