#pragma once
/// The rotation-free Kirchhoff-Love shell triangle (EBST, docs/theory/shell.md): strain energy,
/// residual and tangent of one patch (the triangle and the three nodes opposite its sides, 18
/// translational unknowns), total Lagrangian, plane stress: exactly incompressible (1/κ = 0, KL9)
/// or nearly, with the bulk modulus κ of the mixed element's pressure term (KL12).
///
///   Π_e = A0 ∫ W₂(I + 2ε + 2ζκ) dζ                                          (KL13, KL14)
///
/// The kernels are templates on the material: any type with `PointResponse evaluate(const Mat3d&
/// F) const`, or `evaluate_at(q, F)` for a model whose points carry history (q is then the
/// through-thickness point). No heap allocation; inputs are const, outputs owned by the caller:
/// thread-safe. Units: positions [mm], energy [mJ = N mm], residual [N], tangent [N/mm].
#include <algorithm>

#include "element/shell_geometry.hpp"
#include "element/shell_plane_stress.hpp"
#include "element/shell_section.hpp"
#include "element/shell_strains.hpp"
#include "material/registry.hpp"

namespace plisse::shell {

/// The energy per unit reference area Ψ [N/mm] and its derivatives with respect to the
/// generalized strains s (KL13, KL15, KL16).
struct SectionResponse {
  double energy = 0.0;
  StrainVec gradient = StrainVec::Zero();
  StrainMat hessian = StrainMat::Zero();
  double min_J = 1.0;  ///< the smallest det F at the points through the thickness
};

/// Whether the element could be evaluated, and its energy.
struct ShellStatus {
  bool ok = true;       ///< false: a point's C₂ is not positive definite, the triangle has
                        ///< collapsed, or the model rejected F; outputs are then zero
  double energy = 0.0;  ///< Π_e [mJ]
  double min_J = 1.0;   ///< the smallest det F at the points through the thickness (1 when
                        ///< exactly incompressible)
};

/// C₂(ζ) = I + 2 (ε + ζ κ) in the element's frame (KL7).
inline Mat2d in_plane_C(const StrainVec& s, double zeta) {
  Mat2d C;
  C << 1.0 + 2.0 * (s(0) + zeta * s(3)), 2.0 * (s(2) + zeta * s(5)), 2.0 * (s(2) + zeta * s(5)),
      1.0 + 2.0 * (s(1) + zeta * s(4));
  return C;
}

/// Ψ and its derivatives at the generalized strains s (KL13, KL15, KL16); inverse_bulk_modulus
/// 1/κ [1/MPa], 0 for exact incompressibility (KL9, KL12). Without `with_hessian` the Hessian is
/// left zero: a residual needs Ψ and its gradient only. Throws InadmissibleDeformation where the
/// model or C₂ is inadmissible.
template <class Material>
SectionResponse integrate_section(const ShellSection& section, const Mat3d& frame,
                                  const StrainVec& s, const Material& material,
                                  double inverse_bulk_modulus, bool with_hessian = true) {
  SectionResponse r;
  for (int q = 0; q < section.n_points; ++q) {
    const double zeta = section.zeta[q];
    const double w = section.weight[q];
    const PlaneStressResponse p = evaluate_plane_stress(material, q, in_plane_C(s, zeta), frame,
                                                        inverse_bulk_modulus, with_hessian);
    r.min_J = std::min(r.min_J, p.J);
    r.energy += w * p.W;
    r.gradient.head<3>() += 2.0 * w * p.dW;  // ∂c/∂ε = 2, ∂c/∂κ = 2ζ (KL15)
    r.gradient.tail<3>() += 2.0 * w * zeta * p.dW;
    if (!with_hessian) continue;
    r.hessian.topLeftCorner<3, 3>() += 4.0 * w * p.d2W;  // (KL16)
    r.hessian.topRightCorner<3, 3>() += 4.0 * w * zeta * p.d2W;
    r.hessian.bottomRightCorner<3, 3>() += 4.0 * w * zeta * zeta * p.d2W;
  }
  if (with_hessian)
    r.hessian.bottomLeftCorner<3, 3>() = r.hessian.topRightCorner<3, 3>().transpose();
  return r;
}

/// Π_e (KL14) at nodal displacements u [mm]; inverse_bulk_modulus 1/κ [1/MPa] (KL12). Throws
/// InadmissibleDeformation where the state is inadmissible.
template <class Material>
double compute_shell_energy(const ShellGeometry& g, const ShellSection& section, const PatchVec& u,
                            const Material& material, double inverse_bulk_modulus) {
  const ShellKinematics k = compute_shell_kinematics(g, g.X + u);
  return g.area *
         integrate_section(section, g.frame, k.strains, material, inverse_bulk_modulus, false)
             .energy;
}

/// Energy, residual r = ∂Π_e/∂u (KL15) and, when K is given, tangent K = ∂²Π_e/∂u∂u (KL16) of one
/// patch at nodal displacements u [mm]; inverse_bulk_modulus 1/κ [1/MPa], 0 for exact
/// incompressibility (KL12). r and K are overwritten. Rows and columns of a missing neighbour are
/// zero (KL8).
template <class Material>
ShellStatus assemble_shell(const ShellGeometry& g, const ShellSection& section, const PatchVec& u,
                           const Material& material, double inverse_bulk_modulus, PatchVec& r,
                           PatchMat* K) {
  ShellStatus status;
  // r and K are assigned whole below (or zeroed on an inadmissible state): zeroing them first
  // would write the 36 x 36 tangent of every patch twice.
  try {
    const ShellKinematics k = compute_shell_kinematics(g, g.X + u);
    const SectionResponse psi = integrate_section(section, g.frame, k.strains, material,
                                                  inverse_bulk_modulus, K != nullptr);
    const StrainGradient D = compute_strain_gradient(g, k);
    status.energy = g.area * psi.energy;
    status.min_J = psi.min_J;
    r.noalias() = g.area * D.transpose() * psi.gradient;
    if (K != nullptr) {
      // 36 x 6 times 6 x 36: coefficient-wise, not the blocked GEMM, which packs its operands
      // for an inner dimension of only 6.
      const Eigen::Matrix<double, kPatchDofs, 6> DtH = g.area * D.transpose() * psi.hessian;
      K->noalias() = DtH.lazyProduct(D);
      add_strain_hessians(g, k, g.area * psi.gradient, *K);
    }
  } catch (const InadmissibleDeformation&) {
    status.ok = false;
    status.energy = 0.0;
    r.setZero();
    if (K != nullptr) K->setZero();
  }
  return status;
}

/// assemble_shell for the model held by `material` (one std::visit per element).
ShellStatus assemble_shell(const ShellGeometry& g, const ShellSection& section, const PatchVec& u,
                           const AnyMaterial& material, double inverse_bulk_modulus, PatchVec& r,
                           PatchMat* K);

/// compute_shell_energy for the model held by `material`.
double compute_shell_energy(const ShellGeometry& g, const ShellSection& section, const PatchVec& u,
                            const AnyMaterial& material, double inverse_bulk_modulus);

}  // namespace plisse::shell
