// SPDX-License-Identifier: MIT
#include "error_agreement.hpp"

#include <chrono>
#include <thread>

namespace fddem::app {

ErrorAgreement::ErrorAgreement(int n_processes)
{
    if (n_processes > 1) {
        MPI_Comm_dup(MPI_COMM_WORLD, &comm_);
    }
}

ErrorAgreement::~ErrorAgreement()
{
    int is_finished = 0;
    MPI_Finalized(&is_finished);
    if (comm_ != MPI_COMM_NULL && is_finished == 0) {
        MPI_Comm_free(&comm_);
    }
}

bool ErrorAgreement::every_rank_failed(double wait_seconds)
{
    if (comm_ == MPI_COMM_NULL) {
        return true;
    }
    MPI_Request request = MPI_REQUEST_NULL;
    MPI_Ibarrier(comm_, &request);
    const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::duration<double>(wait_seconds);
    int is_done = 0;
    while (MPI_Test(&request, &is_done, MPI_STATUS_IGNORE) == MPI_SUCCESS && is_done == 0) {
        if (std::chrono::steady_clock::now() > deadline) {
            // Once more: the last rank may have joined while this one slept.
            MPI_Test(&request, &is_done, MPI_STATUS_IGNORE);
            return is_done != 0;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return is_done != 0;
}

} // namespace fddem::app
