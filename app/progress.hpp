// SPDX-License-Identifier: MIT
#pragma once
// Progress of a run: a redrawn status line on a terminal, plain periodic lines otherwise. Once a
// write fails (stderr closed: `fddem run … 2>&1 | head`), nothing more is printed; the run goes
// on.

#include <chrono>
#include <cstdio>
#include <optional>
#include <string>

namespace fddem::app {

class Progress {
public:
    Progress(std::FILE* stream, bool is_terminal, long log_interval,
             std::optional<double> end_time);
    /// The time loop starts now, at this step and time (a restarted run's are not 0): rate and
    /// ETA count from here.
    void start(long step, double time);
    /// Called after every step.
    void update(long step, double time, int outer_iterations);
    /// Ends the status line (terminal) before other messages are printed.
    void finish();
    /// A message on its own line, keeping the status line intact.
    void message(const std::string& text);

    /// "h:mm:ss" for a number of seconds (negative or unknown: "-").
    [[nodiscard]] static std::string clock_text(double seconds);

private:
    /// Writes `text` and flushes it, unless the stream has failed before; a failure closes it.
    void write(const std::string& text);
    /// "step N  t = … s (…%)  K outer  … steps/s  ETA h:mm:ss"
    [[nodiscard]] std::string status_text(long step, double time, int outer_iterations,
                                          std::chrono::steady_clock::time_point now) const;

    std::FILE* stream_;
    bool is_terminal_;
    long log_interval_;
    std::optional<double> end_time_;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point last_draw_;
    bool has_line_ = false;
    bool is_closed_ = false; ///< a write failed: print no more
    long first_step_ = 0;
    double first_time_ = 0.0; ///< [s]
};

} // namespace fddem::app
