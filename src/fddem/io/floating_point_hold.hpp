// SPDX-License-Identifier: MIT
#pragma once
/// Extreme (but valid) inputs can overflow what is read or derived from them (`1e400` in the
/// TOML parser, a derived stiffness of 1e300²); the reader checks each value and names the
/// inputs. Floating-point traps (which the tests enable, STYLE.md §10) are held meanwhile, and
/// the caller's environment is restored afterwards.

#include <cfenv>

namespace fddem {

class FloatingPointHold {
public:
    FloatingPointHold() { std::feholdexcept(&saved_); }
    ~FloatingPointHold() { std::fesetenv(&saved_); }
    FloatingPointHold(const FloatingPointHold&) = delete;
    FloatingPointHold& operator=(const FloatingPointHold&) = delete;
    FloatingPointHold(FloatingPointHold&&) = delete;
    FloatingPointHold& operator=(FloatingPointHold&&) = delete;

private:
    std::fenv_t saved_{};
};

} // namespace fddem
