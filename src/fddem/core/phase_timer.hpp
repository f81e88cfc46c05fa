// SPDX-License-Identifier: MIT
#pragma once
/// Wall-clock seconds per phase of the time step, for summary.json: a ScopedPhase adds the time
/// from its construction to its destruction to one phase (RAII, so an early return or a throw
/// still counts), and the part of it spent in fddem's own MPI calls (halo exchanges and
/// collectives, read from a running counter the Communicator keeps).

#include <array>
#include <chrono>
#include <cstddef>
#include <string_view>

namespace fddem {

/// The phases of a time step that summary.json reports (and "other" for the rest).
enum class Phase : std::size_t { momentum, pressure, coupling, contact };
inline constexpr std::size_t n_phases = 4;

/// Their names in summary.json.
[[nodiscard]] constexpr std::string_view phase_name(Phase phase) noexcept
{
    constexpr std::array<std::string_view, n_phases> names{"momentum", "pressure", "coupling",
                                                           "contact"};
    return names[static_cast<std::size_t>(phase)];
}

/// Seconds spent so far in each phase.
struct PhaseTimes {
    std::array<double, n_phases> seconds{};
    /// Of those, the seconds inside fddem's MPI calls, waiting included (hypre's are not seen).
    std::array<double, n_phases> communication{};
    /// The running total of those calls' seconds (Communicator::seconds_counter()); none on one
    /// process.
    const double* communication_clock = nullptr;

    [[nodiscard]] double operator[](Phase phase) const noexcept
    {
        return seconds[static_cast<std::size_t>(phase)];
    }
    [[nodiscard]] double total() const noexcept
    {
        double sum = 0.0;
        for (double s : seconds) {
            sum += s;
        }
        return sum;
    }
};

/// Adds the wall time from its construction to its destruction to `seconds`.
class ScopedSeconds {
public:
    explicit ScopedSeconds(double& seconds) noexcept
        : seconds_(seconds), start_(std::chrono::steady_clock::now())
    {
    }
    ScopedSeconds(const ScopedSeconds&) = delete;
    ScopedSeconds& operator=(const ScopedSeconds&) = delete;
    ScopedSeconds(ScopedSeconds&&) = delete;
    ScopedSeconds& operator=(ScopedSeconds&&) = delete;
    ~ScopedSeconds()
    {
        seconds_ +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }

private:
    double& seconds_;
    std::chrono::steady_clock::time_point start_;
};

class ScopedPhase {
public:
    ScopedPhase(PhaseTimes& times, Phase phase) noexcept
        : communication_(times.communication[static_cast<std::size_t>(phase)]),
          clock_(times.communication_clock), clock_start_(clock_ != nullptr ? *clock_ : 0.0),
          wall_(times.seconds[static_cast<std::size_t>(phase)])
    {
    }
    ScopedPhase(const ScopedPhase&) = delete;
    ScopedPhase& operator=(const ScopedPhase&) = delete;
    ScopedPhase(ScopedPhase&&) = delete;
    ScopedPhase& operator=(ScopedPhase&&) = delete;
    ~ScopedPhase()
    {
        if (clock_ != nullptr) {
            communication_ += *clock_ - clock_start_;
        }
    }

private:
    double& communication_;
    const double* clock_;
    double clock_start_;
    ScopedSeconds wall_; // the phase's wall time
};

} // namespace fddem
