// SPDX-License-Identifier: MIT
// The words of the case file (io/case_names.hpp): each table reads a name back to its value and
// writes a value as its name, the names of one table are distinct, a word outside the table is
// no value, and the contact models' names are their registry's.

#include "fddem/contact/contact_models.hpp"
#include "fddem/io/case_names.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <variant>

namespace fddem {
namespace {

/// Every row of Enum's table reads back and writes back, under a distinct name.
template <class Enum>
void expect_round_trip(std::size_t n_values)
{
    std::set<std::string> names;
    std::set<Enum> values;
    for (const EnumName<Enum>& entry : case_names(Enum{})) {
        EXPECT_EQ(enum_named<Enum>(entry.name), entry.value) << entry.name;
        EXPECT_EQ(name_of(entry.value), entry.name);
        names.insert(std::string(entry.name));
        values.insert(entry.value);
    }
    EXPECT_EQ(names.size(), n_values);  // no name written twice
    EXPECT_EQ(values.size(), n_values); // every value named (n_values: the enumerators)
}

TEST(CaseNames, EveryTableReadsAndWritesEachOfItsValues)
{
    expect_round_trip<BoundaryKind>(3);
    expect_round_trip<InflowShape>(2);
    expect_round_trip<PressureUpdate>(2);
    expect_round_trip<MomentumSolver>(3);
    expect_round_trip<ConvectionScheme>(2);
    expect_round_trip<PoissonSolverKind>(3);
    expect_round_trip<FftPlanning>(2);
    expect_round_trip<BodyShape>(2);
    expect_round_trip<Motion>(3);
    expect_round_trip<KernelKind>(4);
    expect_round_trip<ContactCoupling>(2);
    expect_round_trip<LubricationInContact>(2);
    expect_round_trip<TimeScheme>(2);
    expect_round_trip<ContactModelKind>(4);
    expect_round_trip<ContactFluidForce>(4);
    expect_round_trip<BodySweep>(2);
    expect_round_trip<MarkerLayout>(3);
}

TEST(CaseNames, AWordOutsideTheTableIsNoValue)
{
    EXPECT_FALSE(enum_named<ContactModelKind>("hooke").has_value());
    EXPECT_FALSE(enum_named<MomentumSolver>("automatic").has_value()); // the case file says auto
    EXPECT_FALSE(enum_named<KernelKind>("").has_value());
}

TEST(CaseNames, NamesSelectWhatTheCaseMeans)
{
    EXPECT_EQ(names_of<ContactModelKind>(), contact_model_names());
    EXPECT_TRUE(std::holds_alternative<HatKernel>(make_kernel(*enum_named<KernelKind>("hat"))));
    EXPECT_TRUE(
        std::holds_alternative<Peskin4Kernel>(make_kernel(*enum_named<KernelKind>("peskin4"))));
    EXPECT_EQ(enum_named<MomentumSolver>("auto"), MomentumSolver::automatic);
    EXPECT_EQ(enum_named<PoissonSolverKind>("auto"), PoissonSolverKind::automatic);
}

} // namespace
} // namespace fddem
