// SPDX-License-Identifier: MIT
#pragma once
// Editing case-file text in tests: one case written out once, its variants made from it.

#include <gtest/gtest.h>

#include <string>

namespace fddem::test {

/// `text` with the first occurrence of `from` replaced by `to`; a test fails if `from` is not
/// there (a variant that silently equals its original would test nothing).
inline std::string replace(std::string text, const std::string& from, const std::string& to)
{
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at == std::string::npos) {
        return text;
    }
    return text.replace(at, from.size(), to);
}

} // namespace fddem::test
