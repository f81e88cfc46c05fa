// SPDX-License-Identifier: MIT
#include "fddem/io/case_reader.hpp"

#include "fddem/core/errors.hpp"
#include "fddem/io/body_entries.hpp"
#include "fddem/io/case_checks.hpp"
#include "fddem/io/case_document.hpp"
#include "fddem/io/case_keys.hpp"
#include "fddem/io/case_limits.hpp"
#include "fddem/io/case_schema.hpp"
#include "fddem/io/contact_derivation.hpp"
#include "fddem/io/floating_point_hold.hpp"
#include "fddem/io/nondimensional_derivation.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace fddem {
namespace {

/// The case as run leaves out the defaults filled in for sides that do not exist or are not
/// walls: both sides of a periodic axis ([walls] velocities and [boundaries] kinds), and the
/// wall velocity of an inflow or outflow side. Read back, they would be given values.
void drop_absent_sides(CaseDocument& doc, const CaseConfig& c)
{
    for (std::size_t d = 0; d < c.domain.periodic.size(); ++d) {
        for (std::size_t side = 0; side < 2; ++side) {
            const char* name = side_names.at(d).at(side);
            if (c.domain.periodic[d] || c.boundaries[d][side] != BoundaryKind::wall) {
                doc.erase("walls", name);
            }
            if (c.domain.periodic[d]) {
                doc.erase("boundaries", name);
            }
        }
    }
}

} // namespace

CaseConfig read_case_string(std::string_view text, const std::string& source_name,
                            const std::vector<std::string>& overrides)
{
    CaseDocument doc(text, source_name, overrides);
    CaseConfig c = read_keys(doc, case_schema());
    {
        const FloatingPointHold hold;
        check_limits(doc, c);
        make_bodies(doc, c);
    }
    check_case(doc, c);
    drop_absent_sides(doc, c);
    {
        const FloatingPointHold hold;
        derive_nondimensional(doc, c);
        check_bodies(doc, c);
        derive_contact(doc, c);
    }
    record_body_files(doc, c);
    c.as_run = doc.as_run();
    return c;
}

CaseConfig read_case(const std::string& path, const std::vector<std::string>& overrides)
{
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) {
        throw InputError(path, 0, "", "is a directory, not a case file (give the case's .toml)");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw InputError(path, 0, "", "cannot open the case file");
    }
    std::ostringstream text;
    text << in.rdbuf();
    return read_case_string(text.str(), path, overrides);
}

} // namespace fddem
