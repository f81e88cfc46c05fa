// SPDX-License-Identifier: MIT
#pragma once
/// Wall-clock seconds per phase of the time step, for summary.json: a ScopedPhase adds the time
/// from its construction to its destruction to one phase (RAII, so an early return or a throw
/// still counts).

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

class ScopedPhase {
public:
    ScopedPhase(PhaseTimes& times, Phase phase) noexcept
        : seconds_(times.seconds[static_cast<std::size_t>(phase)]),
          start_(std::chrono::steady_clock::now())
    {
    }
    ScopedPhase(const ScopedPhase&) = delete;
    ScopedPhase& operator=(const ScopedPhase&) = delete;
    ScopedPhase(ScopedPhase&&) = delete;
    ScopedPhase& operator=(ScopedPhase&&) = delete;
    ~ScopedPhase()
    {
        seconds_ +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }

private:
    double& seconds_;
    std::chrono::steady_clock::time_point start_;
};

} // namespace fddem
