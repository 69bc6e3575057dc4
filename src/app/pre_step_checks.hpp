#pragma once
/// The checks `plisse run` makes before its first step beyond those of reading the case
/// (parse_case_file), loading its mesh against it (load_perturbed_mesh) and building the parts
/// of the model (build_model_parts), which refuse on their own: one table, which `plisse check`
/// walks too, so that the two commands judge a case alike (a case `check` calls valid is not
/// refused by `run` before it solves). Needs no PETSc.
#include <functional>
#include <string>
#include <vector>

#include "app/model_builder.hpp"
#include "case/case.hpp"
#include "mesh/mesh.hpp"

namespace plisse::app {

/// When a check can run: once the mesh is loaded and checked against the case, or once the
/// parts of the model are built too.
enum class PreStepStage { mesh, parts };

/// One check: its name (for the docs and the tests), its stage, and the function that throws
/// the InputError of a refused case. `parts` is null at the `mesh` stage.
struct PreStepCheck {
  std::string name;
  PreStepStage stage = PreStepStage::mesh;
  std::function<void(const Case& c, const Mesh& mesh, const ModelParts* parts)> check;
};

/// The table, in the order `plisse run` applies it:
/// - "element and scheme": unsupported_features (a mesh whose order does not fit the element,
///   a scheme not available), refused at the first;
/// - "curved elements": every 10-node tetrahedron of `element: taylor-hood` has a positive
///   Jacobian determinant at its corners and quadrature points (theory/taylor_hood.md); a
///   refused one is named (1-based, in the order of the file's tetrahedra) with the Gmsh option
///   that straightens it;
/// - "rigid pieces": check_rigid_pieces.
const std::vector<PreStepCheck>& pre_step_checks();

/// Runs the checks of `stage`, in the table's order. `parts` must be given at the `parts` stage.
/// Throws the InputError of the first check that refuses.
void run_pre_step_checks(PreStepStage stage, const Case& c, const Mesh& mesh,
                         const ModelParts* parts = nullptr);

}  // namespace plisse::app
