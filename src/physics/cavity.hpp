#pragma once
/// A fluid-filled cavity bounded by a tagged surface (closed, or closed by symmetry planes through
/// the origin): volume control or an ideal gas, with the cavity pressure as a global unknown
/// (docs/theory/cavities.md).
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "physics/cap_closure.hpp"
#include "physics/cavity_settings.hpp"
#include "physics/dirichlet.hpp"
#include "physics/model_term.hpp"
#include "physics/surface.hpp"

namespace plisse {

/// The cavity term: the gauge pressure p_c [MPa] is one global unknown that pushes on the wall
/// like a follower pressure (virtual work p_c dV), and its equation is
///   -(V(x) - V_c(p_c, t)) = 0   (cavities.md, C7)
/// with V_c the prescribed volume (C8) or the volume of a polytropic ideal gas at p_c, less a
/// rigid reservoir's (C9).
/// History columns `pressure:<name>` (p_c) and `volume:<name>` (V, C1).
/// A cavity whose reference volume is below this fraction of A^{3/2} (A the wall's area) starts
/// flat: V0 = 0, round-off of the wall's size (cavities.md, C8).
inline constexpr double kFlatVolumeTolerance = 1e-12;

class CavityTerm : public ModelTerm {
 public:
  /// Borrows `mesh`. The wall's rims that one of `caps` ties are closed by that cap (C14), so the
  /// gas pushes on the cap too. `imperfection` [mm] is the largest distance the case's
  /// imperfection moved a node of `mesh` (0: none): a wall that lay flat before it encloses at
  /// most that distance times its area, of either sign. Throws InputError at
  /// `cavity.surface.place` when the surface breaks the closure rule (C2: an open edge that no
  /// symmetry plane or cap closes) or encloses a negative volume beyond that, and when a wall
  /// that starts flat (|V0| below kFlatVolumeTolerance A^{3/2} + imperfection A, A its area) has
  /// gas or a volume ratio, or the prescribed final volume is not positive. `constraints` decide
  /// symmetric(); `mirror_planes` (the model's, dirichlet.hpp) scale `full_volume:<name>`.
  CavityTerm(const Cavity& cavity, const Mesh& mesh,
             const std::vector<ConstrainedComponent>& constraints, int mirror_planes,
             const std::vector<CapNodes>& caps = {}, double imperfection = 0.0);

  int n_global_unknowns() const override { return 1; }
  void set_first_global_dof(int dof) override { pressure_dof_ = dof; }
  /// (p_c, u) and (u, p_c) for every displacement component of the wall's nodes, (p_c, p_c), and
  /// each closing cap's rim nodes with one another (add_cap_closure_couplings).
  void add_couplings(std::vector<std::pair<int, int>>& pairs) const override;
  /// True when pressure_stiffness_is_symmetric holds for the wall (cavities.md, C5 and C11).
  bool symmetric() const override { return symmetric_; }
  /// 1: the cavity pressure borders the tangent as [K g; g^T d] with d = dV_c/dp_c <= 0 (0 for
  /// volume control, -V_c/(p_c + p_amb) < 0 for the gas), which adds exactly one negative pivot to
  /// a stable state (docs/theory/stability.md, S6).
  int negative_directions() const override;
  /// Residual (C6)-(C7) and bordered tangent (C10)-(C11). Throws plisse::Error when a gas
  /// cavity's absolute pressure p_c + p_amb is not positive (the step is then cut back).
  void assemble(double t, std::span<const double> x, std::span<double> residual,
                TangentSink* tangent) override;
  std::vector<std::string> history_columns() const override;
  std::vector<double> history_values(double t, std::span<const double> x) const override;

  /// V(x) [mm^3] (C1, with the caps' cones C15) and the reference volume V0 = V(0).
  double volume(std::span<const double> x) const;
  double reference_volume() const { return reference_volume_; }
  /// Volume control: the prescribed volume at the end of the ramp (C8).
  double final_volume() const;
  /// The reservoir's volume in the modelled part: `reservoir_volume` over the copies of the part
  /// in the whole body (full_body_factor) [mm^3].
  double modelled_reservoir() const;
  /// V_c(p_c, t) and its derivative d V_c / d p_c (C8, C9).
  double fluid_volume(double p_c, double t) const;
  double fluid_volume_derivative(double p_c, double t) const;
  /// Full-state index of p_c (valid after set_first_global_dof).
  int pressure_dof() const { return pressure_dof_; }

 private:
  const Mesh& mesh_;
  Cavity cavity_;
  /// Adds one face's share of 6 V (C1, C12), residual (C6) and bordered tangent (C10-C11).
  template <int N>
  void add_face(const SurfaceFace& face, double p, std::span<const double> x,
                std::span<double> residual, TangentSink* tangent, double& six_volume) const;

  std::vector<SurfaceFace> faces_;    ///< oriented with the body's outward normal, 3 or 6 nodes
  std::vector<int> nodes_;            ///< distinct nodes of the wall (corners and edge nodes)
  std::vector<CapClosure> closures_;  ///< the caps that close the wall's rims (C14)
  double reference_volume_ = 0.0;
  bool symmetric_ = false;
  int pressure_dof_ = -1;
  int full_body_factor_ = 1;  ///< copies of the modelled part in the whole body (full_body_factor)
};

}  // namespace plisse
