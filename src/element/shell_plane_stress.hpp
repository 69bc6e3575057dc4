#pragma once
/// Incompressible plane stress for any model of the registry (docs/theory/shell.md, KL9-KL11):
/// the energy W₂(C₂) = Ŵ(C₂ ⊕ 1/det C₂) of a point of the shell and its first and second
/// derivatives with respect to the three independent components (C11, C22, C12) of the in-plane
/// right Cauchy-Green tensor C₂, from the model's own W, P = ∂W/∂F and A = ∂P/∂F. No heap;
/// thread-safe.
#include "core/types.hpp"
#include "element/shell_geometry.hpp"
#include "material/inadmissible_deformation.hpp"
#include "material/point_response.hpp"

namespace plisse::shell {

/// W₂ and its derivatives with respect to c = (C11, C22, C12), C12 = C21 one unknown.
struct PlaneStressResponse {
  double W = 0.0;             ///< [MPa]
  Vec3d dW = Vec3d::Zero();   ///< ∂W₂/∂c [MPa]
  Mat3d d2W = Mat3d::Zero();  ///< ∂²W₂/∂c∂c [MPa], symmetric
};

/// The 3-D deformation gradient of (KL9): F = diag(U, λ3) frameᵀ with U the Cholesky factor of
/// C₂ (UᵀU = C₂) and λ3 = 1/det U, so that det F = 1 and FᵀF = frame (C₂ ⊕ 1/det C₂) frameᵀ.
/// frame: the element's reference frame (columns e1, e2, e3). Throws InadmissibleDeformation when
/// C₂ is not positive definite.
Mat3d plane_stress_deformation(const Mat2d& C2, const Mat3d& frame);

/// (KL10)-(KL11) from the model's response m at F = plane_stress_deformation(C2, frame).
PlaneStressResponse condense_plane_stress(const Mat2d& C2, const Mat3d& frame, const Mat3d& F,
                                          const PointResponse& m);

/// W₂ and its derivatives at C₂ for the model `material` at through-thickness point q (the point
/// index matters only to models with history, material/point_response.hpp). Throws
/// InadmissibleDeformation when C₂ is not positive definite or the model rejects F.
template <class Material>
PlaneStressResponse evaluate_plane_stress(const Material& material, int q, const Mat2d& C2,
                                          const Mat3d& frame) {
  const Mat3d F = plane_stress_deformation(C2, frame);
  return condense_plane_stress(C2, frame, F, evaluate_at_point(material, q, F));
}

}  // namespace plisse::shell
