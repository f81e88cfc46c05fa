// SPDX-License-Identifier: MIT
#pragma once
/// Error types (DESIGN.md §4, STYLE.md §9). The library throws; only app/ maps to exit codes.

#include <stdexcept>
#include <string>

namespace fddem {

/// Bad user input: a case file, a command-line override, an output directory.
/// `file` and `line` locate it (line 0 when unknown), `key` names the case key ("" if none).
class InputError : public std::runtime_error {
public:
    InputError(std::string file, int line, std::string key, const std::string& message)
        : std::runtime_error(message), file_(std::move(file)), line_(line), key_(std::move(key))
    {
    }
    [[nodiscard]] const std::string& file() const noexcept { return file_; }
    [[nodiscard]] int line() const noexcept { return line_; }
    [[nodiscard]] const std::string& key() const noexcept { return key_; }
    /// One line: "file:line: key: message".
    [[nodiscard]] std::string formatted() const;

private:
    std::string file_;
    int line_;
    std::string key_;
};

/// A numerical failure during a run: NaN, divergence of the outer loop.
class NumericalError : public std::runtime_error {
public:
    NumericalError(long step, double time, std::string where, const std::string& what)
        : std::runtime_error(what), step_(step), time_(time), where_(std::move(where))
    {
    }
    [[nodiscard]] long step() const noexcept { return step_; }
    [[nodiscard]] double time() const noexcept { return time_; }
    [[nodiscard]] const std::string& where() const noexcept { return where_; }

private:
    long step_;
    double time_;
    std::string where_;
};

/// Broken internal invariant (a bug in fddem, never bad user data).
class InternalError : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

} // namespace fddem

/// Internal invariants: active in Debug and sanitizer builds, compiled out in Release.
#if defined(FDDEM_DEBUG_ASSERTIONS) || defined(_GLIBCXX_ASSERTIONS)
#define FDDEM_ASSERT(cond, message)                                                                \
    do {                                                                                           \
        if (!(cond)) {                                                                             \
            throw ::fddem::InternalError(std::string(__FILE__) + ":" + std::to_string(__LINE__) +  \
                                         ": assertion '" #cond "' failed: " + (message));          \
        }                                                                                          \
    } while (false)
#else
#define FDDEM_ASSERT(cond, message)                                                                \
    do {                                                                                           \
    } while (false)
#endif
