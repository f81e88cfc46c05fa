// SPDX-License-Identifier: MIT
#include "fddem/io/build_info.hpp"
#include "fddem/io/case_schema.hpp"

#include <cstdio>

#include "commands.hpp"

namespace fddem::app {

int info_command(bool keys, bool markdown)
{
    if (keys) {
        std::fputs(describe_keys(markdown).c_str(), stdout);
        return exit_success;
    }
    for (const auto& [name, value] : build_info()) {
        std::printf("%-14s %s\n", name.c_str(), value.c_str());
    }
    return exit_success;
}

} // namespace fddem::app
