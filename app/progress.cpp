// SPDX-License-Identifier: MIT
#include "progress.hpp"

#include <fmt/format.h>

#include <cmath>

namespace fddem::app {

Progress::Progress(std::FILE* stream, bool is_terminal, long log_interval,
                   std::optional<double> end_time)
    : stream_(stream), is_terminal_(is_terminal), log_interval_(log_interval), end_time_(end_time),
      start_(std::chrono::steady_clock::now()), last_draw_(start_)
{
}

std::string Progress::clock_text(double seconds)
{
    if (!(seconds >= 0.0) || !std::isfinite(seconds)) {
        return "-";
    }
    const long s = std::lround(seconds);
    return fmt::format("{}:{:02}:{:02}", s / 3600, (s / 60) % 60, s % 60);
}

void Progress::start(long step, double time)
{
    start_ = std::chrono::steady_clock::now();
    last_draw_ = start_;
    first_step_ = step;
    first_time_ = time;
}

std::string Progress::status_text(long step, double time, int outer_iterations,
                                  std::chrono::steady_clock::time_point now) const
{
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double rate = elapsed > 0.0 ? static_cast<double>(step - first_step_) / elapsed : 0.0;
    std::string eta = "-";
    std::string percent;
    if (end_time_ && time > first_time_) {
        eta = clock_text(elapsed * (*end_time_ - time) / (time - first_time_));
        percent = fmt::format(" ({:5.1f} %)", 100.0 * time / *end_time_);
    }
    return fmt::format("step {}  t = {:.6g} s{}  {} outer  {:.1f} steps/s  ETA {}", step, time,
                       percent, outer_iterations, rate, eta);
}

void Progress::write(const std::string& text)
{
    if (is_closed_) {
        return;
    }
    // Not fmt::print, which throws when the write fails: SIGPIPE is ignored (app/interrupt.hpp),
    // and a reader that went away must not stop the run.
    is_closed_ = std::fwrite(text.data(), 1, text.size(), stream_) != text.size() ||
                 std::fflush(stream_) != 0;
}

void Progress::update(long step, double time, int outer_iterations)
{
    const auto now = std::chrono::steady_clock::now();
    if (is_terminal_) {
        // Redraw at most four times a second.
        if (std::chrono::duration<double>(now - last_draw_).count() < 0.25) {
            return;
        }
        last_draw_ = now;
        write(fmt::format("\r{}   ", status_text(step, time, outer_iterations, now)));
        has_line_ = true;
        return;
    }
    if (step % log_interval_ == 0) {
        write(status_text(step, time, outer_iterations, now) + "\n");
    }
}

void Progress::finish()
{
    if (has_line_) {
        write("\n");
        has_line_ = false;
    }
}

void Progress::message(const std::string& text)
{
    finish();
    write(text + "\n");
}

} // namespace fddem::app
