#pragma once
/// The model builder: the one place that turns a case into the pieces of the discrete model
/// (material, constrained components, model terms) and validates them against the mesh.
/// `plisse run`, `plisse check` and `plisse wrinkles` all build through it, so a case is judged
/// the same way by every command.
#include <memory>
#include <set>
#include <vector>

#include "case/case.hpp"
#include "material/registry.hpp"
#include "mesh/mesh.hpp"
#include "physics/dirichlet.hpp"
#include "physics/model_term.hpp"
#include "solver/mixed_model.hpp"

namespace plisse::app {

/// What a MixedModel is made of. The terms borrow the mesh they were built on.
struct ModelParts {
  /// The material of every element: the case's `material`, then one per deformable region,
  /// and the rigid regions' elements (built once from the registry).
  ElementMaterials materials;
  /// One per constrained (node, component): the boundary conditions', then the rigid regions'
  /// (every node of their tetrahedra, and the pressure of the nodes only they touch).
  std::vector<ConstrainedComponent> constraints;
  /// One term per load, then per cavity, then per die, in the case's order, then the viscous
  /// damping when solver.viscosity > 0.
  std::vector<std::unique_ptr<ModelTerm>> terms;
  ElementFamily element = ElementFamily::mini;  ///< the case's `element`
};

/// The nodes of `elements` as region_elements gives them: of a solid, tetrahedra (corners and, on
/// a second-order mesh, edge nodes); of a shell, triangles.
std::set<int> nodes_of_elements(const Mesh& mesh, const std::vector<int>& elements);

/// Builds the parts of the case's model on `mesh` (the case's mesh, already checked against the
/// case by load_perturbed_mesh) and validates them: conflicting or non-planar Dirichlet conditions,
/// every displacement prescribed, empty or open surfaces of loads, cavities and dies. Needs no
/// PETSc. Throws InputError at the offending key. Borrows `mesh`.
ModelParts build_model_parts(const Case& c, const Mesh& mesh);

/// A piece of the mesh (tetrahedra, or a shell's triangles, connected through nodes) that some
/// rigid motion moves without meeting a constrained component of `parts`, a die that touches it by
/// the first step's end or a cap's prescribed motion (physics/rigid_motion.hpp): the tangent is
/// singular and every step would fail after its cut-backs. Throws InputError (key `boundary`)
/// naming the piece's size and centre, the free motions and a node they move; cases with surface
/// contacts or solver.viscosity, which can hold or stabilise a piece, are not judged.
/// `plisse check` and `plisse run` call it after build_model_parts.
void check_rigid_pieces(const Case& c, const Mesh& mesh, const ModelParts& parts);

/// The model of `parts` on `mesh` (borrowed). Needs a live PetscSession.
std::unique_ptr<MixedModel> make_model(const Mesh& mesh, ModelParts parts);

/// What the case file allows but this build cannot solve (a mesh whose order does not fit the
/// element, the incremental scheme), each as an InputError naming the key. `plisse run` and
/// `plisse check` refuse the first (app/pre_step_checks).
std::vector<InputError> unsupported_features(const Case& c, const Mesh& mesh);

/// Set-up choices that are legal but usually a mistake, each an InputError naming the key (not
/// thrown): the ramp of a load, a die, a cap, a displacement condition or shell grip that moves,
/// or a rigid region that moves, that ends after solver.end_time (the load or motion is not
/// complete when the run ends) or starts at or after it (never applied). A shorter end_time is
/// legitimate for running part of a case, so these are warnings: `plisse check` prints them and
/// `plisse run` writes them to log.txt. Also a pressure, traction, follower traction or gas
/// pressure above kUnitsWarningFactor times the stiffest material's small-strain Young's modulus
/// (3 mu): most often a value in other units than the material's. With `mesh`, also a pressure load
/// on a surface whose rim a cap ties and that does not name the cap in its `caps` (no end thrust on
/// it), unless a traction or follower traction loads a face of the cap's; and a prescribed
/// displacement or a cap's (its largest component), a die's radius or motion or a rigid region's
/// motion that is not zero but below kUnitsLengthFactor times the mesh's size (its bounding box's
/// diagonal): most often a length in other units than the mesh's.
std::vector<InputError> setup_warnings(const Case& c, const Mesh* mesh = nullptr);

/// How many times the Young's modulus a load may reach before setup_warnings asks about units.
inline constexpr double kUnitsWarningFactor = 10.0;
/// The fraction of the mesh's size below which a prescribed motion or a die's radius makes
/// setup_warnings ask about units.
inline constexpr double kUnitsLengthFactor = 1e-3;

}  // namespace plisse::app
