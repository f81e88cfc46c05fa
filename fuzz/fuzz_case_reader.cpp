// SPDX-License-Identifier: MIT
// libFuzzer target for the case reader (issue 5, item 4): arbitrary bytes go through
// read_case_string, the parse-and-check that `fddem run` does before any work. An InputError is
// the expected answer to bad input; anything else is a finding: a crash, a sanitizer report, a
// hang, another exception, or a case whose "case as run" (written to every run directory and
// read back by `fddem run --restart`) does not read back to itself.
//
// Build and run: tools/fuzz.sh [SECONDS] (preset `fuzz`, clang + libFuzzer + ASan + UBSan).

#include "fddem/core/errors.hpp"
#include "fddem/io/case_reader.hpp"

#include <fmt/format.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

namespace {

[[noreturn]] void report(const char* what, const std::string& detail)
{
    fmt::print(stderr, "fuzz_case_reader: {}: {}\n", what, detail);
    std::abort(); // libFuzzer saves the input as crash-<sha1>
}

/// The case text after its two header lines (which name the source file).
std::string_view body(const std::string& as_run)
{
    const auto blank = as_run.find("\n\n");
    return blank == std::string::npos ? std::string_view(as_run)
                                      : std::string_view(as_run).substr(blank);
}

void read_back(const fddem::CaseConfig& first)
{
    try {
        const fddem::CaseConfig second = fddem::read_case_string(first.as_run, "case.toml");
        if (body(second.as_run) != body(first.as_run)) {
            report("the case as run reads back to a different case", first.as_run);
        }
    } catch (const fddem::InputError& e) {
        report("the case as run does not read back", e.formatted() + "\n" + first.as_run);
    }
}

} // namespace

// NOLINTNEXTLINE(readability-identifier-naming): the name libFuzzer calls
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast): libFuzzer hands out bytes
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    // Bytes after a NUL are one --set override (control characters and all): the case file
    // and the command line, both reach the reader.
    const std::size_t nul = input.find('\0');
    const std::string_view text = input.substr(0, nul);
    std::vector<std::string> overrides;
    if (nul != std::string_view::npos) {
        overrides.emplace_back(input.substr(nul + 1));
    }
    try {
        const fddem::CaseConfig config = fddem::read_case_string(text, "fuzz.toml", overrides);
        read_back(config);
    } catch (const fddem::InputError& e) {
        (void)e.formatted(); // what `fddem run` prints, exit status 2
    } catch (const std::exception& e) {
        report("not an InputError", e.what());
    } catch (...) {
        report("not an InputError", "an exception of unknown type");
    }
    return 0;
}
