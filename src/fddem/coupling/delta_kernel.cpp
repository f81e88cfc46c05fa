// SPDX-License-Identifier: MIT
#include "fddem/coupling/delta_kernel.hpp"

#include "fddem/core/errors.hpp"

namespace fddem {

AnyKernel kernel_from_name(const std::string& name)
{
    if (name == "hat") {
        return HatKernel{};
    }
    if (name == "roma3") {
        return RomaPeskin3Kernel{};
    }
    if (name == "peskin4") {
        return Peskin4Kernel{};
    }
    throw InputError("", 0, "coupling.kernel",
                     "unknown kernel '" + name + "'; expected one of: hat, roma3, peskin4");
}

} // namespace fddem
