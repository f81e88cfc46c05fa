// SPDX-License-Identifier: MIT
#pragma once
// How an error ends a run on several MPI processes. An input error that every rank meets (a bad
// case file, a missing run directory; and rank 0's checks of the run directory and its lock,
// which fddem/run/rank_reasons.hpp's agree_on_input_error makes every rank throw) is said
// once, by rank 0, and then every rank returns its exit status through MPI_Finalize: no
// MPI_Abort. MPI_Abort from the first rank to fail kills the others at once, rank 0 too, and
// rank 0's message could be lost before the launcher forwarded it (seen in CI: a split run's
// bad input ended with status 2 and no message).
//
// Whether every rank met the error is found by a non-blocking barrier on a communicator of its
// own, so that it never matches a collective of the run that a rank without the error may be
// waiting in. A rank whose barrier has not completed after the wait falls back to MPI_Abort.

#include <mpi.h>

namespace fddem::app {

class ErrorAgreement {
public:
    /// Duplicates MPI_COMM_WORLD (collective: every rank constructs it at the same point). On
    /// one process, or without MPI, nothing.
    explicit ErrorAgreement(int n_processes);
    ErrorAgreement(const ErrorAgreement&) = delete;
    ErrorAgreement& operator=(const ErrorAgreement&) = delete;
    ErrorAgreement(ErrorAgreement&&) = delete;
    ErrorAgreement& operator=(ErrorAgreement&&) = delete;
    ~ErrorAgreement();

    /// True once every rank has called it within `wait_seconds` of this rank's call (every
    /// rank met an error); false when the wait ends first, and then this rank's barrier is left
    /// pending: the caller ends the job with MPI_Abort.
    [[nodiscard]] bool every_rank_failed(double wait_seconds);

private:
    MPI_Comm comm_ = MPI_COMM_NULL;
};

} // namespace fddem::app
