#pragma once
/// A rigid end cap: the nodes of a tagged surface tied to a reference point that moves rigidly,
/// by one Lagrange multiplier per tied node and component (docs/theory/caps.md, G4-G7). Each of
/// the cap's six motions (the reference point's displacement u_c and the rotation vector θ) is
/// either prescribed, ramped, or free under an applied force or moment.
#include <array>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "physics/cap_settings.hpp"
#include "physics/dirichlet.hpp"
#include "physics/model_term.hpp"

namespace plisse {

class RigidCap : public ModelTerm {
 public:
  /// Ties every node of `cap.surface` (corners and edge nodes; on a shell the nodes of the edge
  /// or face tag of that name) to the cap, except the components that `constraints` already
  /// prescribe (the boundary condition wins there). Borrows `mesh`. Throws InputError at
  /// `cap.place` when nothing is left to tie, or when a shell's tied nodes lie on one line about
  /// which the cap is free to turn.
  RigidCap(const Cap& cap, const Mesh& mesh, const std::vector<ConstrainedComponent>& constraints);

  /// One multiplier per tie, then one unknown per free motion of the cap.
  int n_global_unknowns() const override;
  void set_first_global_dof(int dof) override { first_dof_ = dof; }
  void add_couplings(std::vector<std::pair<int, int>>& pairs) const override;
  /// Each tie is a constraint whose multiplier borders the tangent: one negative pivot each (S5).
  int negative_directions() const override { return static_cast<int>(ties_.size()); }
  void assemble(double t, std::span<const double> x, std::span<double> residual,
                TangentSink* tangent) override;
  /// `force_x:<name>` ... (the force of the cap on the body [N]), `moment_x:<name>` ... (its
  /// moment about the displaced reference point [N mm]), `ux:<name>` ... (the reference point's
  /// displacement [mm]) and `rx:<name>` ... (the rotation vector [rad]).
  std::vector<std::string> history_columns() const override;
  std::vector<double> history_values(double t, std::span<const double> x) const override;

  /// A cap whose six motions are all prescribed holds each tie (its node, along its component);
  /// otherwise it holds the body's motion along each prescribed one, its tied nodes moving as one
  /// (exact when it ties every component of its nodes). A cap free in all six holds nothing but
  /// ties its nodes together (a zero direction).
  std::vector<RigidHold> rigid_holds(double t) const override;
  /// The cap's six motions (u_c, θ) at (t, x): prescribed ones from the ramp, free ones from x.
  std::array<double, 6> motion(double t, std::span<const double> x) const;
  int n_ties() const { return static_cast<int>(ties_.size()); }

 private:
  struct Tie {
    int node, component;
  };
  /// On a shell: InputError at the cap when `nodes` lie on one line and the cap's turn about it
  /// is free, which nothing would hold (the cap holds the edge's nodes, not its slope: G8).
  void refuse_free_turn_about_a_line(const std::set<int>& nodes) const;
  /// Full-state index of the multiplier of tie k, and of free motion m (0..5; -1 if prescribed).
  int multiplier_dof(int k) const { return first_dof_ + k; }
  int motion_dof(int m) const {
    return free_index_[m] < 0 ? -1 : first_dof_ + n_ties() + free_index_[m];
  }

  const Mesh& mesh_;
  Cap settings_;
  Vec3d point_;                    ///< the reference point X_c [mm]
  std::vector<Tie> ties_;          ///< by node, then component
  std::vector<int> nodes_;         ///< the tied nodes (each with at least one tie)
  std::vector<int> first_tie_;     ///< per tied node: index of its first tie; nodes_.size() + 1
  std::array<int, 6> free_index_;  ///< index among the free motions, -1 if prescribed
  int n_free_ = 0;
  int first_dof_ = -1;
};

}  // namespace plisse
