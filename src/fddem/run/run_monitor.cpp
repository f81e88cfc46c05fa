// SPDX-License-Identifier: MIT
#include "fddem/run/run_monitor.hpp"

#include <csignal>

namespace fddem {

const char* signal_name(int signal) noexcept
{
    switch (signal) {
    case SIGINT:
        return "SIGINT";
    case SIGTERM:
        return "SIGTERM";
    case SIGHUP:
        return "SIGHUP";
    default:
        return "a signal";
    }
}

} // namespace fddem
