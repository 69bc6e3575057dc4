#pragma once
/// What the shell triangle reports besides its energy (docs/theory/shell.md, KL19-KL21): the
/// deformation gradient of its mid-surface and the thickness averages of the Cauchy stress, in
/// the global basis, so that the outputs of solid elements (principal stretches, σ, von Mises)
/// mean the same on a shell. No heap; inputs const; thread-safe.
#include "element/element_fields.hpp"
#include "element/shell.hpp"

namespace plisse::shell {

/// The mid-surface's deformation gradient, F = [φ̄'_1 φ̄'_2 s t3] [Φ̄'_1 Φ̄'_2 e3]⁻¹ (KL19):
/// φ̄' the mean of the three side gradients (KL3) at the current positions, Φ̄' at the reference
/// ones, t3 and e3 the current and reference normals (KL5), and s the thickness stretch that
/// makes det F = 1 (incompressible, KL9). F = I in the reference, F = Q under a rotation Q, and
/// F = F₀ ⊕ λ3 on a flat patch in a homogeneous in-plane F₀. `u`: nodal displacements [mm].
/// Throws InadmissibleDeformation when the triangle has collapsed or turned over.
Mat3d mid_surface_deformation(const ShellGeometry& g, const PatchVec& u);

/// The Cauchy stress [MPa] of the incompressible plane-stress point with in-plane C₂ and 2nd
/// Piola-Kirchhoff stress S₂ (both 2 × 2, in the element's local frame), in the global basis
/// (KL20): σ = Q (U S₂ Uᵀ ⊕ 0) Qᵀ, with U the upper Cholesky factor of C₂ (UᵀU = C₂) and Q the
/// columns of the current in-plane frame ê1 (along the image of e1), ê2 = t3 × ê1, t3.
Mat3d plane_stress_cauchy(const Mat2d& C2, const Mat2d& S2, const Mat3d& current_frame);

/// The current frame of KL20 from F of KL19 and the current normal t3.
Mat3d current_frame(const Mat3d& F, const ShellGeometry& g, const Vec3d& t3);

/// Output averages of one patch at displacements u [mm] (KL21): the Cauchy stress averaged
/// through the thickness, J = 1 (exactly incompressible), its von Mises stress, and as the
/// pressure -tr σ̄ / 3, the mean of the thickness stress that incompressibility eliminated (the
/// plane-stress shell has no pressure unknown; for the isotropic models it equals the pressure
/// field a solid element reports, whose isochoric stress is deviatoric). Throws
/// InadmissibleDeformation where the state is inadmissible.
template <class Material>
ElementFields compute_shell_fields(const ShellGeometry& g, const ShellSection& section,
                                   const PatchVec& u, const Material& material) {
  const ShellKinematics k = compute_shell_kinematics(g, g.X + u);
  const Mat3d frame = current_frame(mid_surface_deformation(g, u), g, k.normal);
  ElementFields f = zero_element_fields();
  for (int q = 0; q < section.n_points; ++q) {
    const Mat2d C2 = in_plane_C(k.strains, section.zeta[q]);
    const PlaneStressResponse p = evaluate_plane_stress(material, q, C2, g.frame);
    Mat2d S2;  // S₂ = 2 ∂W₂/∂C₂ with C12 = C21 one component (KL10)
    S2 << 2.0 * p.dW(0), p.dW(2), p.dW(2), 2.0 * p.dW(1);
    f.cauchy += section.weight[q] / section.thickness * plane_stress_cauchy(C2, S2, frame);
  }
  f.J = 1.0;
  f.von_mises = von_mises_stress(f.cauchy);
  f.pressure = -f.cauchy.trace() / 3.0;
  return f;
}

}  // namespace plisse::shell
