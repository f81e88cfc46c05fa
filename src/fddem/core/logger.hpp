// SPDX-License-Identifier: MIT
#pragma once
/// The library never prints: it reports through a Logger the caller hands in (STYLE.md §5).

#include <string_view>

namespace fddem {

class Logger {
public:
    Logger() = default;
    Logger(const Logger&) = default;
    Logger& operator=(const Logger&) = default;
    Logger(Logger&&) = default;
    Logger& operator=(Logger&&) = default;
    virtual ~Logger() = default;
    virtual void info(std::string_view message) = 0;
    virtual void warn(std::string_view message) = 0;
};

/// Discards everything (tests, benchmarks).
class NullLogger final : public Logger {
public:
    void info(std::string_view /*message*/) override {}
    void warn(std::string_view /*message*/) override {}
};

} // namespace fddem
