// SPDX-License-Identifier: MIT
// fddem validate: runs the verification and validation cases against their references and
// writes a Markdown report with plots. The comparisons and the plots are in
// tools/validate.py (numpy, matplotlib: Debian's python3 packages); this command finds that
// script in the source tree fddem was built from and runs it on this very program.

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "commands.hpp"
#include "python_program.hpp"

namespace fddem::app {

int validate_command(const ValidateOptions& options)
{
    const std::filesystem::path script =
        std::filesystem::path(FDDEM_SOURCE_DIR) / "tools" / "validate.py";
    if (!std::filesystem::exists(script)) {
        std::fprintf(stderr,
                     "fddem: validate needs the source tree fddem was built from (%s not "
                     "found)\n",
                     script.c_str());
        return exit_bad_input;
    }
    std::vector<std::string> arguments = {
        python_interpreter(),    script.string(), "--fddem", self_path(), "-o",
        options.output_directory};
    if (options.quick) {
        arguments.emplace_back("--quick");
    }
    if (!options.only.empty()) {
        arguments.emplace_back("--only");
        arguments.emplace_back(options.only);
    }
    return run_child(arguments);
}

} // namespace fddem::app
