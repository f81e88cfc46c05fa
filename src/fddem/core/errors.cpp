// SPDX-License-Identifier: MIT
#include "fddem/core/errors.hpp"

namespace fddem {

std::string InputError::formatted() const
{
    std::string out = file_.empty() ? std::string("input") : file_;
    if (line_ > 0) {
        out.append(":").append(std::to_string(line_));
    }
    out.append(": ");
    if (!key_.empty()) {
        out.append(key_).append(": ");
    }
    out.append(what());
    return out;
}

} // namespace fddem
