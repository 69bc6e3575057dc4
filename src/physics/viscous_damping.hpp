#pragma once
/// Viscous stabilisation: an artificial nodal damping force that resists the displacement
/// increment of the current step, to pass snap-throughs and wrinkle onset quasi-statically
/// (docs/theory/viscous.md, eqs. Z1-Z4).
///
///   F_i = c_i (u_i - u_i^n) / Δt,   c_i = η V_i / ℓ²,   Δt = t - t^n > 0                   (Z1)
///   dF_i / du_i = c_i / Δt I (diagonal, symmetric positive)                                (Z2)
///   D^{n+1} = D^n + Σ_i F_i · (u_i - u_i^n)   at the converged state of the step             (Z3)
/// η [MPa s] is `solver.viscosity`, ℓ [mm] a length (wall thickness), V_i [mm³] the lumped
/// reference volume of node i (Σ_e V_e / 4 on linear tetrahedra, Z5 on 10-node ones, Σ_T A_T t_T /
/// 3 on a shell's triangles, Z6), u^n and t^n the last accepted state. F = 0 when Δt <= 0, and on
/// constrained components (fixed, prescribed, symmetry): their residual rows are not equations, so
/// a force there would not act but would count in D. The force is not part of the physics: the user
/// checks that the dissipated energy D stays small against the strain energy (history column
/// `dissipated_energy`).
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "physics/dirichlet.hpp"
#include "physics/model_term.hpp"

namespace plisse {

/// Mean length of the tetrahedron edges of `mesh` [mm] (each edge counted once per tetrahedron
/// it belongs to), or of a shell's triangle edges (once per triangle, die_surface.hpp's
/// mean_edge_length). Throws plisse::Error for a mesh without tetrahedra, or a shell without
/// triangles.
double mean_edge_length(const Mesh& mesh);

class ViscousDamping : public ModelTerm {
 public:
  /// `viscosity` η [MPa s] > 0, `length` ℓ [mm] > 0 (both finite; plisse::Error otherwise);
  /// `constraints`: the components that get no damping. Borrows nothing: the nodal volumes are
  /// computed here. The accepted state starts at u^n = 0, t^n = 0, D = 0 (the reference
  /// configuration at the start of a run).
  ViscousDamping(const Mesh& mesh, double viscosity, double length,
                 const std::vector<ConstrainedComponent>& constraints = {});

  /// Adds F_i (Z1) to the displacement rows of `residual` and c_i / Δt (Z2) to the diagonal of
  /// `tangent`; remembers t as the time of the step being solved.
  void assemble(double t, std::span<const double> x, std::span<double> residual,
                TangentSink* tangent) override;
  /// Adds the step's dissipation (Z3) at the converged x, then u^n = u(x), t^n = t of the last
  /// assemble.
  void accept_step(std::span<const double> x) override;

  /// [t^n, D, u^n (3 per node)].
  std::vector<double> save_state() const override;
  /// Restores save_state(); plisse::Error if the size does not fit the mesh or a value is not
  /// finite.
  void load_state(std::span<const double> state) override;

  /// {"dissipated_energy"} [mJ = N mm].
  std::vector<std::string> history_columns() const override;
  std::vector<double> history_values(double t, std::span<const double> x) const override;

  double dissipated_energy() const { return dissipated_energy_; }  ///< D [mJ]
  /// c_i = η V_i / ℓ² [N s / mm] of one component (0 when it is constrained). V_i is the lumped
  /// volume of node i: Σ_e V_e / 4 over its linear tetrahedra; for 10-node tetrahedra the
  /// diagonally scaled lumping V_e ∫ N_i² dV / Σ_b ∫ N_b² dV (Z5: V_e / 36 per corner and
  /// 4 V_e / 27 per edge node of a straight one), which stays positive; on a shell, a third of
  /// each triangle's area times its thickness (Z6).
  double damping_coefficient(int node, int component) const {
    return coefficient_[3 * static_cast<std::size_t>(node) + static_cast<std::size_t>(component)];
  }

 private:
  /// Σ_i F_i · (u_i - u_i^n) at state x and step Δt > 0 (the work of Z3).
  double step_work(std::span<const double> x, double dt) const;

  std::vector<double> coefficient_;  ///< c_i [N s / mm], 3 per node (0: constrained component)
  std::vector<double> u_accepted_;   ///< u^n, 3 per node [mm]
  double t_accepted_ = 0.0;          ///< t^n [s]
  double t_current_ = 0.0;           ///< t of the last assemble [s]
  double dissipated_energy_ = 0.0;   ///< D [mJ]
};

}  // namespace plisse
