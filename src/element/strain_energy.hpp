#pragma once
/// Stored (strain) energy of one MINI element at a state.
///
///   E_e = ∫_Ωe W(F) dV + 1/(2κ) ∫_Ωe p_h² dV                                              (SE1)
///
/// W is the isochoric energy of the material (W(Ī1, Ī2) of the registry), F = I + Grad u_h with
/// the bubble (the same four points and F as element/mini.hpp), p_h the P1 pressure. The second
/// term is the volumetric energy of the nearly incompressible form; it is 0 for exact
/// incompressibility (1/κ = 0).
///
/// Why p²/(2κ) and not κ/2 (J - 1)²: the discrete pressure equation of the mixed form (R3)
/// holds weakly, r_p,a = -∫ N_a ((J - 1) + p_h/κ) dV = 0 for every pressure node a. Since
/// E_e = Π_e - Σ_a p_a r_p,a (Π_e the mixed functional U1 of element/mini.hpp), summed over the
/// mesh E = Π at every state that satisfies the pressure equations, with E_e >= 0 term by term
/// (W >= 0 for the registry's models). Along a displacement path that keeps the bubble and the
/// pressure equations satisfied,
///   dE/ds = dΠ/ds - p · dr_p/ds = r_u · du/ds + r_b · db/ds + r_p · dp/ds = r_u · du/ds,   (SE2)
/// the work of the internal forces (tests/unit/element/strain_energy_test.cpp checks SE2 by
/// finite differences). For p_h = -κ (J - 1) pointwise the two volumetric forms agree; κ/2 (J-1)²
/// would not satisfy (SE2) with the mixed residual, because p_h is only the L2 projection of
/// -κ (J - 1) onto the P1 pressures.
#include "core/error.hpp"
#include "element/mini_integrals.hpp"
#include "element/mini_layout.hpp"
#include "element/tet_geometry.hpp"
#include "material/energy_density.hpp"
#include "material/registry.hpp"

namespace plisse::mini {

/// The two parts of (SE1) [mJ = N mm].
struct StrainEnergy {
  double isochoric = 0.0;   ///< ∫ W dV
  double volumetric = 0.0;  ///< 1/(2κ) ∫ p_h² dV (0 when exactly incompressible)
  double total() const { return isochoric + volumetric; }
};

/// (SE1) for any model of the registry (W from compute_energy_density).
///   x_e: nodal displacements [mm] and pressures [MPa] (mini_layout.hpp); bubble: the converged
///   bubble of the state [mm] (as returned by assemble_mini); inverse_bulk_modulus: 1/κ [1/MPa],
///   0 for exact incompressibility.
/// Throws plisse::Error when det F <= 0 at a quadrature point (a converged state never has it),
/// and InadmissibleDeformation when the material rejects F (e.g. Gent past its limit).
template <class Material>
StrainEnergy compute_strain_energy(const TetGeometry& g, const ElemVec& x_e, const Material& mat,
                                   double inverse_bulk_modulus, const BubbleVec& bubble) {
  const NodalState s = gather_nodal_state(g, x_e);
  StrainEnergy e;
  for (int q = 0; q < kQuadPoints; ++q) {
    const PointKinematics k = compute_point_kinematics(g, s, bubble, q);
    PLISSE_CHECK(k.J > 0.0, "strain energy: det F = " << k.J << " <= 0 at quadrature point " << q);
    e.isochoric += g.weight[q] * compute_energy_density(mat, k.F);
    // p_h² is quadratic: the degree-2 rule integrates it exactly.
    e.volumetric += g.weight[q] * 0.5 * inverse_bulk_modulus * k.p * k.p;
  }
  return e;
}

/// (SE1) for the model held by `material` (one std::visit per element).
StrainEnergy compute_strain_energy(const TetGeometry& g, const ElemVec& x_e,
                                   const AnyMaterial& material, double inverse_bulk_modulus,
                                   const BubbleVec& bubble);

}  // namespace plisse::mini
