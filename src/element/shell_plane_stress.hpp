#pragma once
/// Plane stress for any model of the registry (docs/theory/shell.md, KL9-KL12): the energy
/// W₂(C₂) = Ŵ(C₂ ⊕ C33) of a point of the shell, with the thickness stretch squared C33 that makes
/// the normal stress zero, and its first and second derivatives with respect to the three
/// independent components (C11, C22, C12) of the in-plane right Cauchy-Green tensor C₂, from the
/// model's own W, P = ∂W/∂F and A = ∂P/∂F. Exactly incompressible (1/κ = 0), C33 = 1/det C₂
/// (KL9); nearly incompressible (1/κ > 0), Ŵ gains the volumetric energy κ/2 (J - 1)² of the
/// mixed element's pressure term and C33 is found by Newton's method (KL12). No heap;
/// thread-safe.
#include <cmath>
#include <concepts>

#include "core/types.hpp"
#include "element/shell_geometry.hpp"
#include "material/inadmissible_deformation.hpp"
#include "material/isochoric_invariants.hpp"
#include "material/point_response.hpp"

namespace plisse::shell {

/// W₂ and its derivatives with respect to c = (C11, C22, C12), C12 = C21 one unknown.
struct PlaneStressResponse {
  double W = 0.0;             ///< [MPa]
  Vec3d dW = Vec3d::Zero();   ///< ∂W₂/∂c [MPa]
  Mat3d d2W = Mat3d::Zero();  ///< ∂²W₂/∂c∂c [MPa], symmetric
  double C33 = 1.0;           ///< λ3², the thickness stretch squared at the point [-]
  double J = 1.0;             ///< det F = √(det C₂ C33) [-]
};

/// A model that gives its energy's derivatives in (Ī1, Ī2) (material/isochoric_invariants.hpp).
template <class Material>
concept HasInvariantDerivatives = requires(const Material& m) {
  { m.invariant_derivatives(1.0, 1.0) } -> std::same_as<InvariantDerivatives>;
};

/// A model whose points carry history (material/point_response.hpp: evaluate_at).
template <class Material>
concept HasPointHistory = requires(const Material& m, int q, const Mat3d& F) {
  m.evaluate_at(q, F);
};

/// A model whose energy is W(Ī1, Ī2) alone (neo-Hookean, Mooney-Rivlin, Yeoh, Gent, Arruda-Boyce,
/// Fung) and whose points carry no history: its exactly incompressible plane stress has the
/// closed form (KL11a).
template <class Material>
concept InvariantModel = HasInvariantDerivatives<Material> && !HasPointHistory<Material>;

/// det C₂, tr C₂ and the invariants I1 = tr C₂ + 1/det C₂, I2 = det C₂ + tr C₂ / det C₂ of
/// C₂ ⊕ 1/det C₂ (KL11a).
struct PlaneStressInvariants {
  double det = 1.0;
  double trace = 2.0;
  double I1 = 3.0;
  double I2 = 3.0;
};

/// The invariants of (KL11a) at C₂. Throws InadmissibleDeformation when C₂ is not positive
/// definite, with the message of plane_stress_deformation.
PlaneStressInvariants plane_stress_invariants(const Mat2d& C2);

/// (KL11a): W₂ = W(I1, I2) (C33 = 1/det C₂, J = 1) and its derivatives in c = (C11, C22, C12) by
/// the chain rule from the model's derivatives d at (I1, I2) of `invariants`, those of C₂. The
/// same function of C₂ as (KL9)-(KL11) evaluate through F, P and A; without `with_hessian` d2W is
/// left zero.
PlaneStressResponse condense_invariants(const Mat2d& C2, const PlaneStressInvariants& invariants,
                                        const InvariantDerivatives& d, bool with_hessian = true);

/// The 3-D energy Ŵ(C₂ ⊕ C33) + κ/2 (J - 1)² of a point and its derivatives with respect to the
/// four components (C11, C22, C12, C33), at a given C33 (KL12).
struct ThickPointResponse {
  double W = 0.0;                                 ///< [MPa]
  Eigen::Vector4d dW = Eigen::Vector4d::Zero();   ///< [MPa]
  Eigen::Matrix4d d2W = Eigen::Matrix4d::Zero();  ///< [MPa], symmetric
  double J = 1.0;                                 ///< √(det C₂ C33) [-]
};

/// Newton's method for C33 stops once its step is below this fraction of C33; the response is
/// then corrected to first order in the step (KL12). What is left is of the order of the step's
/// square in W₂ and its gradient, and of the step times κ/μ in the Hessian (whose volumetric part
/// grows with κ): the tolerance is tight so that the tangent stays consistent at large κ.
/// Newton's convergence is quadratic, so this costs at most one step more than a loose one.
inline constexpr double kThicknessStepTolerance = 1e-12;
/// At most this many Newton steps for C33 before the point is reported inadmissible.
inline constexpr int kMaxThicknessIterations = 40;

/// The 3-D deformation gradient of a plane-stress point: F = diag(U, √C33) frameᵀ with U the
/// upper Cholesky factor of C₂ (UᵀU = C₂), so that FᵀF = frame (C₂ ⊕ C33) frameᵀ. frame: the
/// element's reference frame (columns e1, e2, e3). Throws InadmissibleDeformation when C₂ is not
/// positive definite or C33 is not positive.
Mat3d plane_stress_deformation(const Mat2d& C2, const Mat3d& frame, double C33);

/// The same with C33 = 1/det C₂ (KL9): det F = 1.
Mat3d plane_stress_deformation(const Mat2d& C2, const Mat3d& frame);

/// (KL10)-(KL11) from the model's response m at F = plane_stress_deformation(C2, frame); without
/// `with_hessian` d2W is left zero (a residual needs W and dW only, and d2W is most of the work).
PlaneStressResponse condense_plane_stress(const Mat2d& C2, const Mat3d& frame, const Mat3d& F,
                                          const PointResponse& m, bool with_hessian = true);

/// Ŵ + κ/2 (J - 1)² and its derivatives in (C11, C22, C12, C33) (KL12) from the model's response m
/// at F = plane_stress_deformation(C2, frame, C33); bulk_modulus κ [MPa] > 0.
ThickPointResponse thick_point_response(const Mat2d& C2, const Mat3d& frame, double C33,
                                        const Mat3d& F, const PointResponse& m,
                                        double bulk_modulus);

/// The response of W₂ at the C33 of (KL12) from the 3-D response at the last iterate, whose
/// Newton step for C33 is `step`: the static condensation of C33 (the Schur complement of
/// ∂²Ŵ/∂C33²), to first order in the step.
PlaneStressResponse condense_thickness(const ThickPointResponse& w, double C33, double step);

/// The next iterate for C33 from C33 and its Newton step, kept within [C33/4, 4 C33].
double next_thickness_iterate(double C33, double step);

/// W₂ and its derivatives at C₂ for the model `material` at through-thickness point q (the point
/// index matters only to models with history, material/point_response.hpp), exactly
/// incompressible when inverse_bulk_modulus = 0 (KL9-KL11), else with the bulk modulus
/// κ = 1/inverse_bulk_modulus [MPa] (KL12). Throws InadmissibleDeformation when C₂ is not
/// positive definite, the model rejects F, or no positive C33 makes the normal stress zero.
/// Without `with_hessian` an exactly incompressible point leaves d2W zero (the nearly
/// incompressible one needs it for C33 and returns it anyway).
template <class Material>
PlaneStressResponse evaluate_plane_stress(const Material& material, int q, const Mat2d& C2,
                                          const Mat3d& frame, double inverse_bulk_modulus = 0.0,
                                          bool with_hessian = true) {
  if (inverse_bulk_modulus == 0.0) {
    if constexpr (InvariantModel<Material>) {
      const PlaneStressInvariants I = plane_stress_invariants(C2);
      return condense_invariants(C2, I, material.invariant_derivatives(I.I1, I.I2), with_hessian);
    }
    const Mat3d F = plane_stress_deformation(C2, frame);
    return condense_plane_stress(C2, frame, F, evaluate_at_point(material, q, F), with_hessian);
  }
  const double bulk_modulus = 1.0 / inverse_bulk_modulus;
  double C33 = 1.0 / C2.determinant();  // the incompressible value: close when κ >> μ
  for (int iteration = 0; iteration < kMaxThicknessIterations; ++iteration) {
    const Mat3d F = plane_stress_deformation(C2, frame, C33);
    const ThickPointResponse w =
        thick_point_response(C2, frame, C33, F, evaluate_at_point(material, q, F), bulk_modulus);
    const double step = -w.dW(3) / w.d2W(3, 3);
    if (!(w.d2W(3, 3) > 0.0) || !std::isfinite(step)) break;
    if (std::abs(step) <= kThicknessStepTolerance * C33) return condense_thickness(w, C33, step);
    C33 = next_thickness_iterate(C33, step);
  }
  throw InadmissibleDeformation("shell: no thickness stretch makes the normal stress zero");
}

/// λ3 = √C33 at C₂ (KL9, KL12): 1/√det C₂ when inverse_bulk_modulus = 0, else the root of KL12.
/// Throws as evaluate_plane_stress.
template <class Material>
double thickness_stretch(const Material& material, int q, const Mat2d& C2, const Mat3d& frame,
                         double inverse_bulk_modulus) {
  if (inverse_bulk_modulus == 0.0) {
    const double det = C2.determinant();
    if (!(det > 0.0) || !std::isfinite(det)) {
      throw InadmissibleDeformation("shell: C2 is not positive definite inside the thickness");
    }
    return 1.0 / std::sqrt(det);
  }
  return std::sqrt(evaluate_plane_stress(material, q, C2, frame, inverse_bulk_modulus).C33);
}

}  // namespace plisse::shell
