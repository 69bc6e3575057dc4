#pragma once
/// What the shell triangle reports besides its energy (docs/theory/shell.md, KL19-KL25): the
/// deformation gradient of its mid-surface and the thickness averages of the Cauchy stress, in
/// the global basis, so that the outputs of solid elements (principal stretches, σ, von Mises)
/// mean the same on a shell; and what only a shell has: its current thickness, the stress
/// resultants, the change of curvature, and the stresses and stretches of its two faces. No heap;
/// inputs const; thread-safe.
#include <array>
#include <cmath>

#include "element/element_fields.hpp"
#include "element/shell.hpp"

namespace plisse::shell {

/// The mid-surface's deformation gradient, F = [φ̄'_1 φ̄'_2 s t3] [Φ̄'_1 Φ̄'_2 e3]⁻¹ (KL19):
/// φ̄' the triangle's mean gradient (KL4a) at the current positions, Φ̄' at the reference
/// ones, t3 and e3 the current and reference normals (KL5), and s the thickness stretch that
/// makes det F = J, the mid-surface's volume ratio (1 when incompressible, KL9; that of KL12
/// otherwise). F = I in the reference, F = Q under a rotation Q, and F = F₀ ⊕ λ3 on a flat patch
/// in a homogeneous in-plane F₀. `u`: nodal displacements [mm]. Throws InadmissibleDeformation
/// when the triangle has collapsed or turned over.
Mat3d mid_surface_deformation(const ShellGeometry& g, const PatchVec& u, double J = 1.0);

/// The Cauchy stress [MPa] of the plane-stress point with in-plane C₂, 2nd Piola-Kirchhoff
/// stress S₂ (both 2 × 2, in the element's local frame) and volume ratio J = det F, in the global
/// basis (KL20): σ = Q (U S₂ Uᵀ ⊕ 0) Qᵀ / J, with U the upper Cholesky factor of C₂ (UᵀU = C₂)
/// and Q the columns of the current in-plane frame ê1 (along the image of e1), ê2 = t3 × ê1, t3.
Mat3d plane_stress_cauchy(const Mat2d& C2, const Mat2d& S2, const Mat3d& current_frame, double J);

/// The current frame of KL20 from F of KL19 and the current normal t3.
Mat3d current_frame(const Mat3d& F, const ShellGeometry& g, const Vec3d& t3);

/// S₂ = 2 ∂W₂/∂C₂ of a plane-stress response, C12 = C21 one component (KL10).
inline Mat2d second_piola_kirchhoff(const PlaneStressResponse& p) {
  Mat2d S2;
  S2 << 2.0 * p.dW(0), p.dW(2), p.dW(2), 2.0 * p.dW(1);
  return S2;
}

/// Output averages of one patch at displacements u [mm] (KL21): the Cauchy stress and J = det F
/// averaged through the thickness (J = 1 when exactly incompressible), the von Mises stress of
/// the mean σ, and as the pressure -tr σ̄ / 3 (the plane-stress shell has no pressure unknown; for
/// the isotropic models this is the pressure field a solid element reports, whose isochoric
/// stress is deviatoric). inverse_bulk_modulus: 1/κ [1/MPa] (KL12). Throws
/// InadmissibleDeformation where the state is inadmissible.
template <class Material>
ElementFields compute_shell_fields(const ShellGeometry& g, const ShellSection& section,
                                   const PatchVec& u, const Material& material,
                                   double inverse_bulk_modulus) {
  const ShellKinematics k = compute_shell_kinematics(g, g.X + u);
  const Mat3d frame = current_frame(mid_surface_deformation(g, u), g, k.normal);
  ElementFields f = zero_element_fields();
  f.J = 0.0;
  for (int q = 0; q < section.n_points; ++q) {
    const Mat2d C2 = in_plane_C(k.strains, section.zeta[q]);
    const PlaneStressResponse p =
        evaluate_plane_stress(material, q, C2, g.frame, inverse_bulk_modulus);
    const double w = section.weight[q] / section.thickness;
    f.cauchy += w * plane_stress_cauchy(C2, second_piola_kirchhoff(p), frame, p.J);
    f.J += w * p.J;
  }
  f.von_mises = von_mises_stress(f.cauchy);
  f.pressure = -f.cauchy.trace() / 3.0;
  return f;
}

/// The faces of the section at which ShellOutputs gives stresses and stretches (KL25).
enum ShellFace { kBottomFace = 0, kMiddleFace = 1, kTopFace = 2 };
inline constexpr int kShellFaces = 3;

/// What a shell element reports through its thickness (KL22-KL25), for the step files. Only
/// doubles (summed over the ranks as a flat array, like ElementFields). Tensors are in the global
/// basis.
struct ShellOutputs {
  double thickness;        ///< current thickness t λ3 of the mid-surface [mm] (KL22)
  Mat3d membrane_force;    ///< N = ∫ σ dz over the current thickness, symmetric, tangent to the
                           ///< current mid-surface [N/mm] (KL23)
  Mat3d bending_moment;    ///< M = ∫ σ z dz, z along t3 from the mid-surface [N mm/mm] (KL23)
  Mat3d curvature_change;  ///< κ = B - b (KL7) as Σ κ_αβ e_α ⊗ e_β, e_α the element's
                           ///< reference frame [1/mm] (KL24)
  std::array<Mat3d, kShellFaces> face_cauchy;     ///< σ at ζ = -t/2, 0, +t/2 [MPa] (KL25)
  std::array<Vec3d, kShellFaces> face_stretches;  ///< principal stretches there, largest first
};

/// Every value zero.
ShellOutputs zero_shell_outputs();

/// One point of the section at reference distance ζ from the mid-surface (KL20, KL22).
struct SectionPoint {
  Mat3d cauchy;              ///< σ [MPa], global basis
  Vec3d stretches;           ///< principal stretches, largest first [-]
  double thickness_stretch;  ///< λ3 = √C33(ζ) [-] (KL9, KL12)
};

/// The point at ζ [mm] of a patch with kinematics k, current frame `frame` (current_frame) and
/// reference frame `reference_frame` (ShellGeometry::frame), for the model `material` at
/// through-thickness point q (a model with history reads that point's), with 1/κ
/// `inverse_bulk_modulus` [1/MPa] (KL12). Throws InadmissibleDeformation where C₂(ζ) is not
/// positive definite or the model rejects F.
template <class Material>
SectionPoint evaluate_section_point(const ShellKinematics& k, double zeta, const Mat3d& frame,
                                    const Mat3d& reference_frame, const Material& material, int q,
                                    double inverse_bulk_modulus) {
  const Mat2d C2 = in_plane_C(k.strains, zeta);
  const PlaneStressResponse p =
      evaluate_plane_stress(material, q, C2, reference_frame, inverse_bulk_modulus);
  return {plane_stress_cauchy(C2, second_piola_kirchhoff(p), frame, p.J),
          principal_stretches(plane_stress_deformation(C2, reference_frame, p.C33)),
          std::sqrt(p.C33)};
}

/// The section's point nearest the reference distance ζ (a face's stress reads the history of
/// the nearest thickness point).
int nearest_section_point(const ShellSection& section, double zeta);

/// z(ζ) = ∫₀^ζ λ3(ζ') dζ' (KL22): the current distance from the mid-surface, along t3, of the
/// material point at reference distance ζ [mm], by the section's Gauss rule mapped onto [0, ζ],
/// λ3 that of the model `material` with 1/κ `inverse_bulk_modulus` (KL9, KL12) in the reference
/// frame `reference_frame`. Throws InadmissibleDeformation where C₂ is not positive definite on
/// the way.
template <class Material>
double current_distance(const ShellSection& section, const StrainVec& strains, double zeta,
                        const Mat3d& reference_frame, const Material& material,
                        double inverse_bulk_modulus) {
  // The rule's points z_g t/2 on [-t/2, t/2] mapped onto [0, ζ]: s = ζ (1/2 + ζ_g / t), weights
  // w_g / t summing to 1.
  double mean_stretch = 0.0;
  for (int g = 0; g < section.n_points; ++g) {
    const double s = zeta * (0.5 + section.zeta[g] / section.thickness);
    mean_stretch +=
        section.weight[g] / section.thickness *
        thickness_stretch(material, nearest_section_point(section, s), in_plane_C(strains, s),
                          reference_frame, inverse_bulk_modulus);
  }
  return zeta * mean_stretch;
}

/// The outputs of one patch at displacements u [mm] (KL22-KL25): the thickness of the
/// mid-surface, the resultants N and M by the section's rule (KL13) with dz = λ3 dζ, the change
/// of curvature, and σ and the principal stretches at the bottom face, the mid-surface and the
/// top face (ζ = -t/2, 0, +t/2; the top face is the one t3 points out of); inverse_bulk_modulus
/// 1/κ [1/MPa] (KL12). Throws InadmissibleDeformation where the state is inadmissible.
template <class Material>
ShellOutputs compute_shell_outputs(const ShellGeometry& g, const ShellSection& section,
                                   const PatchVec& u, const Material& material,
                                   double inverse_bulk_modulus) {
  const ShellKinematics k = compute_shell_kinematics(g, g.X + u);
  const Mat3d frame = current_frame(mid_surface_deformation(g, u), g, k.normal);
  ShellOutputs out = zero_shell_outputs();
  for (int q = 0; q < section.n_points; ++q) {
    const double zeta = section.zeta[q];
    const SectionPoint p =
        evaluate_section_point(k, zeta, frame, g.frame, material, q, inverse_bulk_modulus);
    const double dz = section.weight[q] * p.thickness_stretch;  // dz = λ3 dζ (KL23)
    out.membrane_force += dz * p.cauchy;
    out.bending_moment +=
        dz * current_distance(section, k.strains, zeta, g.frame, material, inverse_bulk_modulus) *
        p.cauchy;
  }
  const std::array<double, kShellFaces> face = {-0.5 * section.thickness, 0.0,
                                                0.5 * section.thickness};
  for (int f = 0; f < kShellFaces; ++f) {
    const SectionPoint p =
        evaluate_section_point(k, face[f], frame, g.frame, material,
                               nearest_section_point(section, face[f]), inverse_bulk_modulus);
    out.face_cauchy[f] = p.cauchy;
    out.face_stretches[f] = p.stretches;
    if (f == kMiddleFace) out.thickness = section.thickness * p.thickness_stretch;
  }
  Mat2d kappa;
  kappa << k.strains(3), k.strains(5), k.strains(5), k.strains(4);
  const Mat32d e = g.frame.leftCols<2>();
  out.curvature_change = e * kappa * e.transpose();
  return out;
}

}  // namespace plisse::shell
