#pragma once
/// The three standard tests of rubber, as homogeneous incompressible deformations, and the nominal
/// stress any registered model gives in them (docs/fit.md, "Test modes"):
///   uniaxial     F = diag(λ, λ^-1/2, λ^-1/2), σ22 = σ33 = 0
///   equibiaxial  F = diag(λ, λ, λ^-2),        σ33 = 0
///   planar       F = diag(λ, 1, 1/λ),         σ33 = 0 (pure shear: the width held)
/// With the isochoric response σ̄ = P Fᵀ (J = 1) and the pressure that makes the free direction
/// traction free, the nominal (first Piola-Kirchhoff) stress along λ is
///   t = (σ̄11 - σ̄ff) / λ,   f = 2 (uniaxial) or 3.
#include <optional>
#include <string>

#include "material/registry.hpp"

namespace plisse {

enum class TestMode { uniaxial, equibiaxial, planar };

/// "uniaxial", "equibiaxial", "planar".
std::string test_mode_name(TestMode mode);
/// The mode called `name`, also "biaxial" for equibiaxial and "pure-shear"/"pure_shear" for
/// planar; nullopt otherwise.
std::optional<TestMode> parse_test_mode(const std::string& name);

/// F of the test at stretch λ > 0.
Mat3d test_deformation(TestMode mode, double stretch);

/// Nominal stress [MPa] of `material` in the test at stretch λ > 0. Throws InadmissibleDeformation
/// where the model is not defined (Gent past its limit).
double nominal_stress(const AnyMaterial& material, TestMode mode, double stretch);

}  // namespace plisse
