#pragma once
/// Rate and history effects added to any hyperelastic model of the registry: finite-strain
/// viscoelasticity (a Prony series of Maxwell elements on the isochoric stress) and Mullins
/// softening (Ogden & Roxburgh's pseudo-elastic damage). Both need internal variables at every
/// material point, carried from one converged step to the next (the element assembly keeps them
/// per quadrature point, in the checkpoint and over the ranks). Formulas and their sources are in
/// docs/theory/materials.md, V1-V7 and MR1-MR6.
///
/// Order of the two effects at a point, with W0, P0 = ∂W0/∂F, A0 = ∂P0/∂F the base model's:
///   1. Mullins (MR1-MR4): Pe = η P0, with η in [1 - 1/r, 1] from W0 and the largest W0 so far;
///   2. viscoelasticity (V1-V5) on the softened isochoric stress Se = F⁻¹ Pe: the overstresses
///      Q_i follow Q̇_i + Q_i / τ_i = β_i Ṡe, integrated exactly for a stress that jumps at the
///      middle of the step (Simo 1987; Holzapfel 2000, section 6.10), and P = Pe + F Σ Q_i.
/// The tangent is exact for the history of the last converged step held fixed, and symmetric: the
/// step's response derives from an incremental potential (V6), so Newton's method and LDLᵀ apply.
#include <array>
#include <span>

#include "core/types.hpp"
#include "material/point_response.hpp"

namespace plisse {

/// Up to three Maxwell elements in parallel with the base model, which is the long-term
/// (equilibrium) response. A term with beta_i = 0 is absent.
struct Viscoelasticity {
  static constexpr int kMaxTerms = 3;
  double beta1 = 0.0;  ///< [-], >= 0: strength of element 1 relative to the equilibrium response
  double tau1 = 0.0;   ///< [s], > 0 when beta1 > 0: its relaxation time
  double beta2 = 0.0;
  double tau2 = 0.0;
  double beta3 = 0.0;
  double tau3 = 0.0;

  /// Number of leading terms present (beta_i > 0).
  int n_terms() const;
  double beta(int i) const { return std::array<double, kMaxTerms>{beta1, beta2, beta3}[i]; }
  double tau(int i) const { return std::array<double, kMaxTerms>{tau1, tau2, tau3}[i]; }
};

/// Ogden & Roxburgh's softening function (MR2): η = 1 - erf((Wmax - W0) / (m + beta Wmax)) / r.
/// Absent when r = 0.
struct MullinsSoftening {
  double r = 0.0;     ///< [-], > 1: η stays above 1 - 1/r
  double m = 0.0;     ///< [MPa], > 0: energy scale of the softening
  double beta = 0.0;  ///< [-], in [0, 1): growth of that scale with the largest energy reached

  bool present() const { return r > 0.0; }
};

/// Doubles of history at one material point: [Wmax] with Mullins softening, then [Se (6), Q_1 (6),
/// ...] with viscoelasticity (symmetric tensors as xx, yy, zz, xy, yz, xz). Zero for an elastic
/// point. All zero is the history of the undeformed body.
struct InelasticLaw {
  Viscoelasticity viscoelastic;
  MullinsSoftening mullins;

  int history_size() const;
  bool elastic() const { return history_size() == 0; }
};

/// The response at one point: the base model's `elastic` response at F (W0, P0, A0), the point's
/// history at the last converged step `converged` (history_size() values) and the time since
/// that step `dt` [s] (0 gives the stress of the converged state itself). Writes the history this
/// response belongs to into `now` (skipped when empty). W is the base model's W0 softened, η W0:
/// the viscous parts store no energy of their own in this measure.
PointResponse evaluate_inelastic(const InelasticLaw& law, const PointResponse& elastic,
                                 const Mat3d& F, std::span<const double> converged,
                                 std::span<double> now, double dt);

}  // namespace plisse
