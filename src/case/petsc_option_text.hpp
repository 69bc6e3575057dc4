#pragma once
/// PETSc options a case (solver.petsc_options) or the command line (--petsc) may give: an
/// allow-list of solver options, each with the type of its value. A run's output goes into its run
/// directory and nowhere else, and PETSc acts on some options as soon as they are inserted
/// (-options_file, -prefix_push), so an option that is not in the list is refused before PETSc
/// sees it: every option that names a file, writes a view or monitor to a file or in binary,
/// reads options, opens a window or a socket or starts a debugger is among those refused.
#include <string>

namespace plisse {

/// Why `options` ("-name [value] -name [value] ...") may not be given, or empty. Each option must
/// be one of the table's (docs/case-file.md, "PETSc options"): its name, after one of the solver
/// prefixes where the table allows them (`fieldsplit_u_`, `fieldsplit_p_`, `stability_`, `st_`),
/// and a value of its type (an integer, a real number, one of its words, an optional true/false,
/// or for a view or monitor nothing or a text format, `::ascii_info`). Names are compared without
/// regard to case, as PETSc does. Refused besides: a word that is neither an option nor the value
/// of the option before it, a quote (PETSc would join the words between quotes) and any character
/// other than printable ASCII and spaces.
std::string petsc_option_problem(const std::string& options);

/// The table of the accepted options for docs/case-file.md (block "petsc-options"): option,
/// prefixes, value and meaning, one row each.
std::string petsc_options_markdown();

}  // namespace plisse
