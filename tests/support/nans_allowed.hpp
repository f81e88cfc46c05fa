// SPDX-License-Identifier: MIT
#pragma once
// For tests that make NaNs or overflows on purpose (a blow-up, to see it caught): while an
// object of this class lives, no floating-point traps (test_main.cpp sets them) on this thread
// or the OpenMP threads.

#include <cfenv>

namespace fddem::test {

class NansAllowed {
public:
    NansAllowed() { set(false); }
    ~NansAllowed() { set(true); }
    NansAllowed(const NansAllowed&) = delete;
    NansAllowed& operator=(const NansAllowed&) = delete;

private:
    static void set(bool trap)
    {
        constexpr int flags = FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW;
#pragma omp parallel
        (void)(trap ? feenableexcept(flags) : fedisableexcept(flags));
        (void)(trap ? feenableexcept(flags) : fedisableexcept(flags));
    }
};

} // namespace fddem::test
