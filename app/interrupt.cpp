// SPDX-License-Identifier: MIT
#include "interrupt.hpp"

#include <csignal>
#include <initializer_list>

namespace fddem::app {
namespace {

// The one global of fddem, by necessity: a signal handler can reach the program only through
// an object of static storage of type volatile std::sig_atomic_t (C++ [support.signal]).
// NOLINTNEXTLINE(cppcoreguidelines-avoid-non-const-global-variables)
volatile std::sig_atomic_t received_signal = 0;

void record_signal(int signal)
{
    received_signal = signal;
}

} // namespace

void install_interrupt_handlers()
{
    struct sigaction action {};
    action.sa_handler = record_signal;
    sigemptyset(&action.sa_mask);
    // SA_RESTART: system calls the signal interrupts (writing outputs) resume instead of
    // failing; SA_RESETHAND: a second Ctrl-C stops a run that takes too long to finish its step.
    action.sa_flags = SA_RESTART | SA_RESETHAND;
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
        sigaction(signal, &action, nullptr);
    }
}

void ignore_broken_pipes()
{
    struct sigaction action {};
    action.sa_handler = SIG_IGN;
    sigemptyset(&action.sa_mask);
    sigaction(SIGPIPE, &action, nullptr);
}

int pending_interrupt() noexcept
{
    return received_signal;
}

} // namespace fddem::app
