// SPDX-License-Identifier: MIT
#include "fddem/coupling/delta_kernel.hpp"

namespace fddem {

AnyKernel make_kernel(KernelKind kind)
{
    switch (kind) {
    case KernelKind::roma3:
        return RomaPeskin3Kernel{};
    case KernelKind::peskin4:
        return Peskin4Kernel{};
    case KernelKind::roma3_smoothed:
        return SmoothedRoma3Kernel{};
    case KernelKind::hat:
        break;
    }
    return HatKernel{};
}

double support_radius(KernelKind kind) noexcept
{
    switch (kind) {
    case KernelKind::roma3:
        return RomaPeskin3Kernel::support_radius;
    case KernelKind::peskin4:
        return Peskin4Kernel::support_radius;
    case KernelKind::roma3_smoothed:
        return SmoothedRoma3Kernel::support_radius;
    case KernelKind::hat:
        break;
    }
    return HatKernel::support_radius;
}

} // namespace fddem
