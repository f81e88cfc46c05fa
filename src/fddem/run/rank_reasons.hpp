// SPDX-License-Identifier: MIT
#pragma once
/// Why a run cannot go on, agreed by every rank (issue 15): a check that each rank makes on its
/// own (a checkpoint's pieces, the memory of its machine) may fail on some ranks only, and
/// rank 0, which alone speaks for the run, must then say the reason of a rank that met it.

#include "fddem/core/errors.hpp"
#include "fddem/grid/communicator.hpp"

#include <exception>
#include <optional>
#include <string>
#include <string_view>

namespace fddem {

/// The `reason` of the lowest rank that has one, on every rank (none if no rank has), followed
/// by "(<where> <rank>)" if that rank is not rank 0. Collective: one maximum, and one all-gather
/// of the texts (each cut to 400 bytes) only when some rank has a reason.
[[nodiscard]] std::optional<std::string> first_reason(const Communicator& ranks,
                                                      const std::optional<std::string>& reason,
                                                      std::string_view where);

/// Runs `check` where `is_checked` (rank 0's checks of the run directory and its lock, or on
/// every rank) and agrees on its InputError: if it throws one on any rank, every rank throws,
/// the rank that met it its own error and the others one with its text. So an input error
/// that rank 0 alone can meet ends every rank alike, and the program ends them together
/// without MPI_Abort (app/error_agreement.hpp). Collective, as first_reason: one maximum, and
/// the texts gathered only when some rank met an error.
template <class Check>
void agree_on_input_error(const Communicator& ranks, bool is_checked, const Check& check)
{
    std::exception_ptr caught;
    std::optional<std::string> failure;
    try {
        if (is_checked) {
            check();
        }
    } catch (const InputError& e) {
        caught = std::current_exception();
        failure = e.formatted();
    }
    const std::optional<std::string> said = first_reason(ranks, failure, "on rank");
    if (caught) {
        std::rethrow_exception(caught);
    }
    if (said) {
        throw InputError("", 0, "", *said); // not said: rank 0 says its own
    }
}

} // namespace fddem
