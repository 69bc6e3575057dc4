#pragma once
/// Contributions to the discrete problem beyond the elements: surface loads, body forces, cavities,
/// contact. A term sees the full state vector of the model (layout below; docs/architecture.md,
/// "The path of a case"), adds to the residual and to the tangent, and may own global scalar
/// unknowns (e.g. a cavity's pressure).
///
/// Full-state layout: kValuesPerNode values per node (ux, uy, uz, p), then the global unknowns of
/// all terms, in the order the terms were added to the model.
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/types.hpp"

namespace plisse {

inline constexpr int kValuesPerNode = 4;
inline int node_dof(int node, int component) { return kValuesPerNode * node + component; }

/// Receives tangent entries by full-state index; the solver maps them to its equations and drops
/// those of constrained components.
class TangentSink {
 public:
  virtual ~TangentSink() = default;
  /// Adds the dense block `values` (row-major, rows.size() x cols.size()).
  virtual void add(std::span<const int> rows, std::span<const int> cols,
                   std::span<const double> values) = 0;
};

/// What a support holds of a rigid motion of the body, u(X) = a + w x (X - c): the component along
/// `direction` of the displacement at `point` (a die touching a node, a cap's prescribed
/// displacement), or with `rotation` the component of w along `direction` (a cap's prescribed
/// rotation). `nodes` move with the support: one node for a die, a cap's tied nodes. A zero
/// `direction` holds nothing but ties `nodes` together (a cap whose six motions are free).
struct RigidHold {
  std::vector<int> nodes;
  Vec3d point = Vec3d::Zero();
  Vec3d direction = Vec3d::UnitZ();  ///< unit
  bool rotation = false;
};

/// One value per mesh node, written as a point field of the step files.
struct NodeField {
  std::string name;
  std::vector<double> values;
};

class ModelTerm {
 public:
  virtual ~ModelTerm() = default;

  /// Global scalar unknowns this term owns.
  virtual int n_global_unknowns() const { return 0; }
  /// Called once by the model with the full-state index of this term's first global unknown.
  virtual void set_first_global_dof(int /*dof*/) {}
  /// Tangent couplings beyond those of the elements (row, column), by full-state index.
  virtual void add_couplings(std::vector<std::pair<int, int>>& /*pairs*/) const {}
  /// True when the couplings add_couplings reports have grown since the model last read them
  /// (asked after every accepted step and restored checkpoint): the model then rebuilds the
  /// tangent's sparsity (e.g. contact between surfaces whose pairs change as the body moves).
  virtual bool couplings_changed() { return false; }
  /// False when the term's tangent is not symmetric (the solver then uses LU instead of LDL^T).
  virtual bool symmetric() const { return true; }
  /// Negative eigenvalues this term's global unknowns add to a stable tangent: a multiplier-like
  /// unknown borders the matrix and adds one negative pivot to an LDL^T factorisation of a stable
  /// state (docs/theory/stability.md, S5). 0 for a term without global unknowns.
  virtual int negative_directions() const { return 0; }

  /// Adds the term's residual at time t and full state x to `residual`, and its tangent
  /// (d residual / d x) to `tangent` when that is not null.
  virtual void assemble(double t, std::span<const double> x, std::span<double> residual,
                        TangentSink* tangent) = 0;

  /// Called after Newton converged at state x, before the step is accepted: an augmented-Lagrangian
  /// term updates its multipliers and returns true when the constraint is not yet met to its
  /// tolerance (the step is then solved again from x with the new multipliers).
  virtual bool update_multipliers(std::span<const double> /*x*/) { return false; }

  /// A step converged at state x (update history such as glued contact points) / was abandoned.
  virtual void accept_step(std::span<const double> /*x*/) {}
  virtual void reject_step() {}

  /// The term's own accepted state (e.g. glued contact points, multipliers) as numbers, for
  /// checkpoints; load_state restores what save_state returned.
  virtual std::vector<double> save_state() const { return {}; }
  virtual void load_state(std::span<const double> /*state*/) {}

  /// Named history columns and their values at (t, x).
  virtual std::vector<std::string> history_columns() const { return {}; }
  virtual std::vector<double> history_values(double /*t*/, std::span<const double> /*x*/) const {
    return {};
  }
  /// What the term holds of a rigid motion of the body in its reference configuration, with its
  /// own motion at time t (the first step's end): a die the nodes it touches then, a cap its
  /// prescribed motions. Loads and cavities hold nothing.
  virtual std::vector<RigidHold> rigid_holds(double /*t*/) const { return {}; }
  /// Point fields at (t, x), each with one value per mesh node (`n_nodes` of them).
  virtual std::vector<NodeField> node_fields(double /*t*/, std::span<const double> /*x*/,
                                             int /*n_nodes*/) const {
    return {};
  }
};

}  // namespace plisse
