// SPDX-License-Identifier: MIT
#include "fddem/run/output_schedule.hpp"

namespace fddem {

bool is_time_reached(const Clock& clock, double target) noexcept
{
    return clock.time >= target - 0.5 * clock.dt;
}

bool take_due_output(const Clock& clock, double interval, double& next_time) noexcept
{
    if (!is_time_reached(clock, next_time)) {
        return false;
    }
    next_time += interval;
    return true;
}

bool take_due_checkpoint(const Clock& clock, long step_interval, double time_interval,
                         double& next_time) noexcept
{
    bool is_due = step_interval > 0 && clock.step % step_interval == 0;
    if (time_interval > 0.0 && is_time_reached(clock, next_time)) {
        is_due = true;
        // Past the current time even if a large step spans several intervals.
        while (next_time < clock.time + 0.5 * clock.dt) {
            next_time += time_interval;
        }
    }
    return is_due;
}

} // namespace fddem
