// SPDX-License-Identifier: MIT
#include "fddem/io/case_names.hpp"

namespace fddem {

std::vector<EnumName<ContactModelKind>> case_names(ContactModelKind /*tag*/)
{
    std::vector<EnumName<ContactModelKind>> names;
    for (const ContactModelEntry& entry : contact_models()) {
        names.push_back({entry.kind, entry.name});
    }
    return names;
}

} // namespace fddem
