// SPDX-License-Identifier: MIT
#pragma once
// SIGINT and SIGTERM end a run cleanly: the handler only records the signal; the time loop
// finishes its step, writes a checkpoint and returns exit_interrupted_base + the signal.

namespace fddem::app {

/// Installs the handlers (once, before the time loop). A second signal of the same kind ends
/// the process at once (the default action is restored when the first one arrives).
void install_interrupt_handlers();

/// The signal received (SIGINT or SIGTERM), 0 if none.
[[nodiscard]] int pending_interrupt() noexcept;

/// "SIGINT", "SIGTERM" or "signal N".
[[nodiscard]] const char* signal_name(int signal) noexcept;

} // namespace fddem::app
