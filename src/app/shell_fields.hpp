#pragma once
/// The cell fields of a shell's step files (docs/output.md, "Step files: cell fields"): what a
/// shell element reports besides the fields every element has (cauchy_stress, von_mises, J,
/// principal_stretches, principal_stresses), from its thickness averages (ElementFields) and its
/// through-thickness outputs (shell::ShellOutputs, docs/theory/shell.md KL21-KL25).
#include <vector>

#include "element/element_fields.hpp"
#include "element/shell_output.hpp"
#include "output/vtu_writer.hpp"

namespace plisse::app {

/// One value set per element, in the order of `fields` and `outputs` (equal sizes; plisse::Error
/// otherwise): `pressure` (-tr σ̄ / 3 of the thickness average, KL21) [MPa], `thickness` [mm],
/// `membrane_force` [N/mm] and `bending_moment` [N] (6 components, VTK's symmetric order),
/// `curvature_change` [1/mm] (6 components), and at the bottom face, the mid-surface and the top
/// face `cauchy_stress_<face>` [MPa] (6 components) and `principal_stretches_<face>` (3
/// components, largest first), <face> being bottom, middle, top.
std::vector<VtuField> shell_cell_fields(const std::vector<ElementFields>& fields,
                                        const std::vector<shell::ShellOutputs>& outputs);

}  // namespace plisse::app
