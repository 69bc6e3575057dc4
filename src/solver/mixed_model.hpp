#pragma once
/// The discrete mixed u-p problem on one mesh: element geometry, material, constraints, the state
/// (nodal displacements and pressures, element bubbles) and the assembly of the residual and the
/// consistent tangent over the free dofs into PETSc objects.
#include <petscmat.h>
#include <petscvec.h>

#include <memory>
#include <vector>

#include "element/mini.hpp"
#include "material/registry.hpp"
#include "mesh/mesh.hpp"
#include "physics/dirichlet.hpp"
#include "physics/model_term.hpp"
#include "solver/dof_map.hpp"

namespace plisse {

/// What went wrong in an assembly, for the step controller and the diagnostics.
struct AssemblyStatus {
  bool ok = true;
  int worst_element = -1;  ///< element with the smallest J (or the failed bubble solve)
  double min_J = 1.0;
};

/// Volume-averaged quantities of the current state (history columns).
struct BodyAverages {
  Mat3d F = Mat3d::Identity();       ///< (1/V0) ∫ F dV
  Mat3d cauchy = Mat3d::Zero();      ///< (1/v) ∫ σ dv  [MPa]
  double volume = 0.0;               ///< deformed volume [mm^3]
};

class MixedModel {
 public:
  /// Borrows `mesh` (must outlive the model). `inverse_bulk_modulus` is 1/κ, 0 for exact
  /// incompressibility. `terms` (loads, ...) are owned by the model; their global unknowns follow
  /// the nodal values in the full state, in the order given.
  MixedModel(const Mesh& mesh, AnyMaterial material, double inverse_bulk_modulus,
             std::vector<ConstrainedComponent> constraints,
             std::vector<std::unique_ptr<ModelTerm>> terms = {});

  const std::vector<std::unique_ptr<ModelTerm>>& terms() const { return terms_; }
  /// True when the tangent is symmetric (all terms symmetric): LDL^T applies.
  bool symmetric() const;

  const Mesh& mesh() const { return mesh_; }
  const DofMap& dofs() const { return dofs_; }
  int n_free() const { return dofs_.n_free(); }

  /// Full state: kPerNode values per node (ux, uy, uz, p), then the terms' global unknowns.
  const std::vector<double>& state() const { return state_; }
  std::vector<double>& state() { return state_; }
  /// Moves to time t: the constrained components take their prescribed values at t and the
  /// external forces their ramped magnitude.
  void set_time(double t);
  double time() const { return time_; }

  /// Fixed external nodal forces [N] on the full dofs (zero on pressure dofs), applied as
  /// ramp.factor(t) * force; the residual is internal minus external force. Replaces earlier ones.
  void set_external_force(std::vector<double> force, Ramp ramp);

  /// Copies the free dofs of the state into `x`, or from `x` into the state.
  void get_free(Vec x) const;
  void set_free(Vec x);

  /// Residual over the free dofs at the current state into `f` (overwritten). Also stores the
  /// full residual, whose constrained entries are the reaction forces [N].
  AssemblyStatus assemble_residual(Vec f);
  /// Consistent tangent over the free dofs into `K` (created by create_matrix; overwritten).
  AssemblyStatus assemble_tangent(Mat K);
  /// An AIJ matrix with the exact sparsity of the tangent, flagged symmetric.
  Mat create_matrix() const;

  /// Lets every term update its multipliers at the current state; true when any term needs
  /// another solve of the step (ModelTerm::update_multipliers).
  bool update_multipliers();

  /// Everything that defines the last converged state, as numbers (checkpoints).
  struct Snapshot {
    std::vector<double> state;    ///< full state
    std::vector<double> bubbles;  ///< kDofBubble per element
    std::vector<std::vector<double>> term_states;  ///< ModelTerm::save_state, per term
  };
  Snapshot snapshot() const;
  /// Makes `s` the current and last converged state. Throws plisse::Error when its sizes do not
  /// fit this model.
  void restore(const Snapshot& s);

  /// Remember / return to the last converged state (state and bubbles).
  void save_converged();
  void restore_converged();
  const std::vector<double>& converged_state() const { return converged_state_; }

  /// Sum of the reaction forces on the constrained dofs of the nodes of `triangles` [N], from
  /// the last assemble_residual.
  Vec3d reaction(const std::vector<int>& triangles) const;

  /// Per-element Cauchy stress, J and von Mises at the current state.
  std::vector<mini::ElementFields> element_fields() const;
  BodyAverages averages() const;

 private:
  void element_dofs(int e, std::array<int, mini::kDof>& full) const;
  mini::ElemVec gather(const std::array<int, mini::kDof>& full) const;

  const Mesh& mesh_;
  AnyMaterial material_;
  double inverse_bulk_modulus_;
  std::vector<ConstrainedComponent> constraints_;
  std::vector<std::unique_ptr<ModelTerm>> terms_;
  DofMap dofs_;
  std::vector<mini::TetGeometry> geometry_;
  std::vector<double> state_, converged_state_;
  std::vector<mini::BubbleVec> bubble_, converged_bubble_;
  std::vector<double> full_residual_;
  std::vector<double> external_force_;
  Ramp external_ramp_;
  double time_ = 0.0;
};

}  // namespace plisse
