#pragma once
/// The discrete mixed u-p problem on one mesh: material, constraints, the state (nodal
/// displacements and pressures, the elements' internal state) and the assembly of the residual
/// and the consistent tangent over the free dofs into PETSc objects. The facade the solvers and
/// the application use; the work is done by its parts:
///   - solver/distribution.hpp: the ranks (node partition, equation numbering by rank, local and
///     owned elements, gathers and reductions);
///   - solver/tangent_layout.hpp: the exact sparsity of the tangent, built once, and the
///     precomputed positions of the element matrices in it;
///   - solver/element_assembly.hpp: the threaded, chunked element loop and its scatter, for the
///     element policy of the model's family (solver/mini_element.hpp: the MINI tetrahedron on a
///     linear mesh; solver/taylor_hood_element.hpp: the Taylor-Hood tetrahedron on a second-order
///     mesh, whose edge nodes carry displacements only: the model constrains their pressure
///     values to 0; solver/shell_element.hpp: the rotation-free shell triangle on the mid-surface
///     of a shell mesh, which has no pressure unknowns: the model constrains the pressure value
///     of every node to 0).
///
/// Distributed runs (more than one rank in PETSC_COMM_WORLD): every rank holds the whole mesh and
/// the whole state; the equations are distributed (solver/partition.hpp). Rank r owns the equations
/// of its nodes, evaluates the elements that touch them (and every term), and fills only its own
/// rows of the residual and the tangent, so that no element contribution crosses ranks. After each
/// Newton update the free values are gathered to every rank (set_free). The members that return
/// whole-model results (element_fields, shell_outputs, strain_energy, reaction, snapshot, the
/// assembly status) are collective and give every rank the same answer. On one rank the matrices
/// and vectors are sequential and everything is as in a serial program.
#include <mpi.h>
#include <petscmat.h>
#include <petscvec.h>

#include <array>
#include <memory>
#include <set>
#include <span>
#include <utility>
#include <variant>
#include <vector>

#include "element/element_family.hpp"
#include "element/element_fields.hpp"
#include "material/registry.hpp"
#include "mesh/mesh.hpp"
#include "physics/dirichlet.hpp"
#include "physics/model_term.hpp"
#include "solver/assembly_status.hpp"
#include "solver/distribution.hpp"
#include "solver/dof_map.hpp"
#include "solver/element_materials.hpp"
#include "solver/element_policy.hpp"
#include "solver/mini_element.hpp"
#include "solver/pressure_twins.hpp"
#include "solver/shell_element.hpp"
#include "solver/taylor_hood_element.hpp"

namespace plisse {

template <ElementPolicy Element>
class ElementAssembly;
class TangentLayout;

/// Volume-averaged quantities of the current state (history columns).
struct BodyAverages {
  Mat3d F = Mat3d::Identity();   ///< (1/V0) ∫ F dV
  Mat3d cauchy = Mat3d::Zero();  ///< (1/v) ∫ σ dv  [MPa]
  double volume = 0.0;           ///< deformed volume [mm^3]
};

class MixedModel {
 public:
  /// Borrows `mesh` (must outlive the model). `inverse_bulk_modulus` is 1/κ, 0 for exact
  /// incompressibility. `terms` (loads, ...) are owned by the model; their global unknowns follow
  /// the nodal values in the full state, in the order given. `family` is the element of every
  /// tetrahedron; the mesh must have its order (mesh_order_of; plisse::Error otherwise). The
  /// shell family takes the triangles of a shell mesh (Mesh::is_shell) instead, and exact
  /// incompressibility only (1/κ = 0; plisse::Error otherwise).
  MixedModel(const Mesh& mesh, AnyMaterial material, double inverse_bulk_modulus,
             std::vector<ConstrainedComponent> constraints,
             std::vector<std::unique_ptr<ModelTerm>> terms = {},
             ElementFamily family = ElementFamily::mini);
  /// The same with a material per element (several models by volume, rigid elements): the
  /// constraints must hold every node of the rigid elements and the pressure of the nodes that
  /// only rigid elements touch (they have no equation of their own). With
  /// `materials.pressure_region` the solid families give every region its own pressure unknowns
  /// where regions meet (solver/pressure_twins.hpp): the state then has a node per twin after the
  /// mesh's nodes, whose displacement values the model holds at 0.
  MixedModel(const Mesh& mesh, ElementMaterials materials,
             std::vector<ConstrainedComponent> constraints,
             std::vector<std::unique_ptr<ModelTerm>> terms = {},
             ElementFamily family = ElementFamily::mini);

  ~MixedModel();
  MixedModel(const MixedModel&) = delete;
  MixedModel& operator=(const MixedModel&) = delete;

  const std::vector<std::unique_ptr<ModelTerm>>& terms() const { return terms_; }
  /// True when the tangent is symmetric (all terms symmetric): LDL^T applies.
  bool symmetric() const;

  const Mesh& mesh() const { return mesh_; }
  /// The material of every element.
  const ElementMaterials& element_materials() const;
  ElementFamily element_family() const { return family_; }
  /// The number of elements: tetrahedra, or the triangles of a shell.
  int n_elements() const;
  const DofMap& dofs() const { return distribution_->dofs(); }
  /// The pressure twins of the regions' interfaces (none without `pressure_region`); the state's
  /// nodes are the mesh's, then these.
  const PressureTwins& pressure_twins() const { return twins_; }
  int n_free() const { return dofs().n_free(); }

  /// The communicator of the algebraic objects: PETSC_COMM_SELF on one rank, else PETSC_COMM_WORLD.
  MPI_Comm comm() const { return distribution_->comm(); }
  int rank() const { return distribution_->rank(); }
  int n_ranks() const { return distribution_->n_ranks(); }
  /// The equations this rank owns: [first_owned_equation, end_owned_equation).
  int first_owned_equation() const { return distribution_->first_equation(); }
  int end_owned_equation() const { return distribution_->end_equation(); }
  int n_owned() const { return distribution_->n_owned(); }
  /// The elements this rank evaluates in an assembly: those touching one of its nodes (all of
  /// them on one rank; the cut elements are evaluated by both sides).
  const std::vector<int>& local_elements() const { return distribution_->local_elements(); }
  /// The elements whose results this rank reports (in output pieces, sums over the body): those
  /// whose first node it owns. Every element is owned by exactly one rank.
  const std::vector<int>& owned_elements() const { return distribution_->owned_elements(); }
  /// A vector over the free dofs with this rank's owned range (for get_free, set_free, residual).
  Vec create_vector() const;
  /// The full state layout (zeros on constrained dofs, pressures in MPa) of a free-dof vector
  /// with the layout of create_vector (pressures weighted as in get_free). Collective.
  std::vector<double> full_from_free(Vec x) const;

  /// Full state: kPerNode values per node (ux, uy, uz, p; the mesh's nodes, then the pressure
  /// twins), then the terms' global unknowns.
  const std::vector<double>& state() const { return state_; }
  std::vector<double>& state() { return state_; }
  /// Moves to time t: the constrained components take their prescribed values at t and the
  /// external forces their ramped magnitude.
  void set_time(double t);
  double time() const { return time_; }
  /// Takes up a run from a checkpoint at time t: the model holds the converged state of t
  /// (restore), which is also the time its points' history was last updated.
  void resume_at(double t);

  /// Fixed external nodal forces [N] on the full dofs (zero on pressure dofs), applied as
  /// ramp.factor(t) * force; the residual is internal minus external force. Replaces earlier ones.
  void set_external_force(std::vector<double> force, Ramp ramp);

  /// The free system's weight of the pressure equations, w = mu / h [N/mm^3] (docs/theory/
  /// mixed_up.md, X1): the free vectors, residuals and tangents below carry the pressure
  /// unknowns as p / w [mm] and their equations (volume change, mm^3) times w [N], so that every
  /// entry of the residual is a force and its norm, which the line search and the convergence
  /// test read, weighs equilibrium and incompressibility alike. mu is the volume average of the
  /// models' small-strain shear moduli, h the edge of the regular tetrahedron of the mean element
  /// volume. A symmetric scaling: the solution, the tangent's symmetry and its inertia are those
  /// of the unweighted system.
  double pressure_weight() const { return pressure_weight_; }

  /// Copies the free dofs of the state into `x` (its owned part), or from `x` into the state
  /// (collective: every rank receives all free values); pressures divided / multiplied by
  /// pressure_weight().
  void get_free(Vec x) const;
  void set_free(Vec x);

  /// Residual over the free dofs at the current state into `f` (overwritten), the pressure
  /// equations times pressure_weight(). Also stores the full residual, unweighted, whose
  /// constrained entries are the reaction forces [N].
  AssemblyStatus assemble_residual(Vec f);
  /// Consistent tangent over the free dofs into `K` (overwritten): d f / d x of the free vectors
  /// above, i.e. pressure rows and columns times pressure_weight(). A matrix from create_matrix
  /// is filled directly in its value array through positions precomputed per element; any other
  /// matrix through MatSetValues (same values, slower).
  AssemblyStatus assemble_tangent(Mat K);
  /// An AIJ matrix with the exact sparsity of the tangent (element couplings and those the terms
  /// declare), entries zero, flagged symmetric when the tangent is: sequential on one rank, else
  /// distributed by the owned equation ranges. The caller owns it.
  Mat create_matrix() const;
  /// Changes whenever the sparsity of the tangent changes (a term's couplings grew after an
  /// accepted step): a matrix made by create_matrix before no longer fits; make a new one.
  int pattern_version() const { return pattern_version_; }

  /// Threads of the element loops; 0 (the default) takes default_assembly_threads()
  /// (solver/thread_counts.hpp: OMP_NUM_THREADS when it is set, else the CPUs per rank once
  /// apply_thread_counts has run, else 1). Results do not depend
  /// on it: elements are evaluated in parallel, a chunk at a time, and their contributions added
  /// in element order, bit for bit as a serial loop does (solver/element_assembly.hpp).
  void set_assembly_threads(int n) { threads_ = n; }
  /// The thread count the element loops use.
  int assembly_threads() const;

  /// Lets every term update its multipliers at the current state; true when any term needs
  /// another solve of the step (ModelTerm::update_multipliers).
  bool update_multipliers();

  /// Everything that defines the last converged state, as numbers (checkpoints).
  struct Snapshot {
    std::vector<double> state;                     ///< full state
    std::vector<double> bubbles;                   ///< elements' internal state (MINI: bubbles)
    std::vector<std::vector<double>> term_states;  ///< ModelTerm::save_state, per term
  };
  Snapshot snapshot() const;
  /// Makes `s` the current and last converged state. Throws plisse::Error when its sizes do not
  /// fit this model.
  void restore(const Snapshot& s);

  /// Remember / return to the last converged state (state, the elements' bubbles and the history
  /// of their points; its time is the current time).
  void save_converged();
  void restore_converged();
  /// Starts from another run's converged state on the same mesh and element: the values of the
  /// mesh's nodes (the first kPerNode * n_nodes of `state`) and the elements' internal state
  /// `internal`; a pressure twin starts from its corner's pressure, the terms' unknowns keep
  /// their start values, the constrained components take this model's
  /// values at the current time, and the result is the converged state. Throws plisse::Error when
  /// the sizes do not fit.
  void continue_from(std::span<const double> state, std::span<const double> internal);
  const std::vector<double>& converged_state() const { return converged_state_; }
  /// Doubles of internal state of the elements (bubbles, then the history of their points): the
  /// size of Snapshot::bubbles and of continue_from's `internal`.
  std::size_t n_internal_values() const;

  /// Sum of the reaction forces on the constrained dofs of the nodes of `triangles` [N], from
  /// the last assemble_residual.
  Vec3d reaction(const std::vector<int>& triangles) const;
  /// The same on the constrained dofs of `nodes` [N]. Collective.
  Vec3d node_reaction(const std::set<int>& nodes) const;
  /// The moment of those reactions about the origin [N mm]: the sum over `nodes` of x × R, x the
  /// node's current position and R its reaction. Collective.
  Vec3d node_reaction_moment(const std::set<int>& nodes) const;

  /// The reaction force at every node [N], 3 values a node (x, y, z): the residual on its
  /// constrained components from the last assemble_residual, zero on its free ones. Collective.
  std::vector<double> nodal_reactions() const;

  /// The volume average of the deformation gradient over each element, (1/V0) ∫ F dV0, at the
  /// current state (for principal stretches; of a shell, its mid-surface's, shell_output.hpp).
  std::vector<Mat3d> element_deformation_gradients() const;

  /// The pressure field at every node of the mesh [MPa]: the nodal unknowns (where regions with
  /// their own pressures meet, the first region's), and on the edge nodes of a Taylor-Hood model
  /// (which carry no pressure unknown) the linear interpolation, the mean of the edge's two
  /// corners (for output).
  std::vector<double> nodal_pressures() const;

  /// The pressure [MPa] element e interpolates at its node `node` (a corner, or on a
  /// Taylor-Hood mesh an edge node): the value of the corner's carrier, the node's own or its
  /// region's twin (solver/pressure_twins.hpp), and at an edge node the mean of the edge's two
  /// corners'. Without twins, nodal_pressures()[node]. Precondition: `node` is a node of e.
  double element_pressure(int e, int node) const;

  /// Per-element Cauchy stress, J and von Mises at the current state (of a shell, thickness
  /// averages: element/shell_output.hpp).
  std::vector<ElementFields> element_fields() const;
  /// Per-element outputs of a shell at the current state (its thickness, the resultants N and M,
  /// the change of curvature, and the faces' stresses and stretches: element/shell_output.hpp,
  /// docs/theory/shell.md KL22-KL25), in the order of the mesh's triangles; empty for a model
  /// of solid elements. Collective.
  std::vector<shell::ShellOutputs> shell_outputs() const;
  BodyAverages averages() const;
  /// The same from element_fields() of the current state, when the caller already has them.
  BodyAverages averages(const std::vector<ElementFields>& fields) const;
  /// Stored energy of the body at the current state [mJ = N mm]: the sum over the elements of
  /// the isochoric W plus, nearly incompressible, the volumetric p^2/(2 kappa) part
  /// (element/strain_energy.hpp; element/taylor_hood.hpp; element/shell.hpp).
  double strain_energy() const;

 private:
  /// This rank's share of the reaction on component k of `node`: the residual of the last
  /// assemble_residual where the component is constrained and the node owned, else 0.
  double local_reaction(int node, int k) const;
  /// The element assembly of the model's family.
  using Elements = std::variant<std::unique_ptr<ElementAssembly<MiniElement>>,
                                std::unique_ptr<ElementAssembly<TaylorHoodElement>>,
                                std::unique_ptr<ElementAssembly<ShellElement>>>;
  /// f(assembly) on the model's element assembly (any family).
  template <class F>
  decltype(auto) visit_elements(F&& f) const {
    return std::visit([&](const auto& e) -> decltype(auto) { return f(std::as_const(*e)); },
                      elements_);
  }
  template <class F>
  decltype(auto) visit_elements(F&& f) {
    return std::visit([&](auto& e) -> decltype(auto) { return f(*e); }, elements_);
  }

  const Mesh& mesh_;
  ElementFamily family_;
  PressureTwins twins_;  ///< the regions' own pressure nodes, after the mesh's
  std::vector<ConstrainedComponent> constraints_;
  std::vector<std::unique_ptr<ModelTerm>> terms_;
  Elements elements_;                           ///< element data and loops
  std::unique_ptr<Distribution> distribution_;  ///< ranks, equation numbering
  std::unique_ptr<TangentLayout> layout_;       ///< sparsity and element positions of K
  int pattern_version_ = 0;                     ///< counts rebuilds of layout_
  /// Rebuilds layout_ from the elements and the terms' current couplings when a term's couplings
  /// grew (ModelTerm::couplings_changed); the distribution stays.
  void refresh_couplings();
  /// The (row, column) couplings all terms declare now (ModelTerm::add_couplings).
  std::vector<std::pair<int, int>> term_couplings() const;
  std::vector<double> state_, converged_state_;
  std::vector<double> full_residual_;
  std::vector<double> external_force_;
  Ramp external_ramp_;
  double time_ = 0.0;
  double converged_time_ = 0.0;  ///< [s] of the last converged state: the history's step starts
  std::vector<double> history_residual_;  ///< scratch of save_converged

  double pressure_weight_ = 1.0;    ///< pressure_weight()
  Vec equation_weights_ = nullptr;  ///< per owned equation: pressure_weight() or 1

  int threads_ = 0;
  std::vector<double> term_residual_;  ///< residual part discarded by assemble_tangent
  std::vector<PetscInt> equations_;    ///< term-sink scratch (MatSetValues path)
};

}  // namespace plisse
