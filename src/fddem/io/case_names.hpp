// SPDX-License-Identifier: MIT
#pragma once
/// The words of the case file for each closed set of choices: one table per enum. The schema
/// (io/case_schema.cpp) lists a key's choices from it and reads the key through it, and what
/// prints a choice back (the run's log and summary) writes it from it.

#include "fddem/simulation/case_config.hpp"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fddem {

template <class Enum>
struct EnumName {
    Enum value;
    std::string_view name; ///< as the case file writes it
};

// One table per enum, in the order `fddem info --keys` lists the choices; the generic functions
// below find a table by the enum's type.

constexpr auto case_names(BoundaryKind /*tag*/)
{
    using enum BoundaryKind;
    return std::to_array<EnumName<BoundaryKind>>(
        {{wall, "wall"}, {inflow, "inflow"}, {outflow, "outflow"}});
}
constexpr auto case_names(InflowShape /*tag*/)
{
    using enum InflowShape;
    return std::to_array<EnumName<InflowShape>>({{uniform, "uniform"}, {parabolic, "parabolic"}});
}
constexpr auto case_names(PressureUpdate /*tag*/)
{
    using enum PressureUpdate;
    return std::to_array<EnumName<PressureUpdate>>(
        {{standard, "standard"}, {rotational, "rotational"}});
}
constexpr auto case_names(MomentumSolver /*tag*/)
{
    using enum MomentumSolver;
    return std::to_array<EnumName<MomentumSolver>>(
        {{automatic, "auto"}, {multigrid, "multigrid"}, {gauss_seidel, "gauss_seidel"}});
}
constexpr auto case_names(ConvectionScheme /*tag*/)
{
    using enum ConvectionScheme;
    return std::to_array<EnumName<ConvectionScheme>>({{central, "central"}, {upwind, "upwind"}});
}
constexpr auto case_names(PoissonSolverKind /*tag*/)
{
    using enum PoissonSolverKind;
    return std::to_array<EnumName<PoissonSolverKind>>(
        {{automatic, "auto"}, {fft, "fft"}, {hypre, "hypre"}});
}
constexpr auto case_names(FftPlanning /*tag*/)
{
    using enum FftPlanning;
    return std::to_array<EnumName<FftPlanning>>({{measure, "measure"}, {estimate, "estimate"}});
}
constexpr auto case_names(BodyShape /*tag*/)
{
    using enum BodyShape;
    return std::to_array<EnumName<BodyShape>>({{disk, "disk"}, {sphere, "sphere"}});
}
constexpr auto case_names(Motion /*tag*/)
{
    using enum Motion;
    return std::to_array<EnumName<Motion>>(
        {{free, "free"}, {prescribed, "prescribed"}, {fixed, "fixed"}});
}
constexpr auto case_names(KernelKind /*tag*/)
{
    using enum KernelKind;
    return std::to_array<EnumName<KernelKind>>(
        {{hat, "hat"}, {roma3, "roma3"}, {peskin4, "peskin4"}, {roma3_smoothed, "roma3_smoothed"}});
}
constexpr auto case_names(TimeScheme /*tag*/)
{
    using enum TimeScheme;
    return std::to_array<EnumName<TimeScheme>>({{euler, "euler"}, {bdf2, "bdf2"}});
}
constexpr auto case_names(MarkerLayout /*tag*/)
{
    using enum MarkerLayout;
    return std::to_array<EnumName<MarkerLayout>>(
        {{paper, "paper"}, {retracted, "retracted"}, {surface, "surface"}});
}
constexpr auto case_names(StepAlgorithm /*tag*/)
{
    using enum StepAlgorithm;
    return std::to_array<EnumName<StepAlgorithm>>({{simple, "simple"}, {projection, "projection"}});
}
constexpr auto case_names(BodySweep /*tag*/)
{
    using enum BodySweep;
    return std::to_array<EnumName<BodySweep>>(
        {{sequential, "sequential"}, {simultaneous, "simultaneous"}});
}
constexpr auto case_names(InnerFluidSource /*tag*/)
{
    using enum InnerFluidSource;
    return std::to_array<EnumName<InnerFluidSource>>({{markers, "markers"}, {volume, "volume"}});
}
constexpr auto case_names(ContactCoupling /*tag*/)
{
    using enum ContactCoupling;
    return std::to_array<EnumName<ContactCoupling>>({{additive, "additive"}, {paper, "paper"}});
}
constexpr auto case_names(ContactFluidForce /*tag*/)
{
    using enum ContactFluidForce;
    return std::to_array<EnumName<ContactFluidForce>>(
        {{automatic, "auto"}, {none, "none"}, {held, "held"}, {always, "always"}});
}
constexpr auto case_names(LubricationInContact /*tag*/)
{
    using enum LubricationInContact;
    return std::to_array<EnumName<LubricationInContact>>({{off, "off"}, {saturated, "saturated"}});
}
constexpr auto case_names(LubricationResolved /*tag*/)
{
    using enum LubricationResolved;
    return std::to_array<EnumName<LubricationResolved>>({{range, "range"}, {shells, "shells"}});
}
constexpr auto case_names(LubricationFilmSolve /*tag*/)
{
    using enum LubricationFilmSolve;
    return std::to_array<EnumName<LubricationFilmSolve>>({{sweep, "sweep"}, {joint, "joint"}});
}
constexpr auto case_names(LubricationCoupling /*tag*/)
{
    using enum LubricationCoupling;
    return std::to_array<EnumName<LubricationCoupling>>({{dem, "dem"}, {implicit, "implicit"}});
}

/// The contact models by the names of their registry (contact/contact_models.cpp).
[[nodiscard]] std::vector<EnumName<ContactModelKind>> case_names(ContactModelKind /*tag*/);

/// The case-file name of `value`.
template <class Enum>
[[nodiscard]] std::string name_of(Enum value)
{
    for (const EnumName<Enum>& entry : case_names(Enum{})) {
        if (entry.value == value) {
            return std::string(entry.name);
        }
    }
    return "?"; // every enumerator has a row (tests/unit/io/test_case_names.cpp)
}

/// The value named `name`, or nothing for a word not in the table.
template <class Enum>
[[nodiscard]] std::optional<Enum> enum_named(std::string_view name)
{
    for (const EnumName<Enum>& entry : case_names(Enum{})) {
        if (entry.name == name) {
            return entry.value;
        }
    }
    return std::nullopt;
}

/// Every name of the table, in its order: a key's choices.
template <class Enum>
[[nodiscard]] std::vector<std::string> names_of()
{
    std::vector<std::string> names;
    for (const EnumName<Enum>& entry : case_names(Enum{})) {
        names.emplace_back(entry.name);
    }
    return names;
}

} // namespace fddem
