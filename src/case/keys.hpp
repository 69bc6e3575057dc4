#pragma once
/// The key tables of docs/case-file.md, generated from the case-file schema (case/case.cpp): what
/// `plisse case-keys` prints and what the unit tests compare the manual with.
#include <string>
#include <vector>

namespace plisse {

/// The sections of a case file in the order the allowed top-level keys are listed, with the mesh
/// generators' options after `mesh` and the accepted PETSc options after `solver`: "title",
/// "mesh", "mesh-options", "material", "boundary", "loads", "cavities", "dies", "probes",
/// "solver", "petsc-options", "output".
std::vector<std::string> case_key_sections();

/// The markdown table of the keys of `section` (key, type, unit, default, range, the variants a
/// key applies to, meaning), followed by the rules between its keys; for "mesh-options" the table
/// of every generator's options (kind, option, type, unit, range, default, meaning), for
/// "petsc-options" the PETSc options a case may give (option, value, meaning). Throws Error
/// for an unknown section.
std::string case_keys_markdown(const std::string& section);

/// `doc` with the content of every generated block replaced by the table of its section. A block
/// is the line `<!-- generated: SECTION -->`, the table, and the line `<!-- end generated -->`;
/// the text around the blocks is kept as it is. Throws Error for an unknown section or a block
/// without its end line.
std::string refresh_case_key_blocks(const std::string& doc);

}  // namespace plisse
