// SPDX-License-Identifier: MIT
#include "fddem/core/time_scheme.hpp"

namespace fddem {

TimeLevels time_levels(TimeScheme scheme, double dt, double previous_dt)
{
    if (previous_dt <= 0.0) {
        return {dt, 0.0};
    }
    const double ratio = dt / previous_dt; // ω
    if (scheme == TimeScheme::euler) {
        return {dt, 0.0, ratio};
    }
    return {dt * (1.0 + ratio) / (1.0 + 2.0 * ratio), ratio * ratio / (1.0 + 2.0 * ratio), ratio};
}

} // namespace fddem
