#pragma once
/// Least-squares fit of a registered material model to nominal stress-stretch data of the
/// uniaxial, equibiaxial and planar tests (docs/fit.md). The residual of a point is the relative
/// error (t_model - t_data) / t_data, so every point weighs alike whatever its stress; the
/// minimiser is Eigen's Levenberg-Marquardt with a forward-difference Jacobian, started from
/// several points derived from the data's small-strain modulus, the best result kept.
#include <string>
#include <vector>

#include "material/homogeneous_test.hpp"
#include "material/registry.hpp"

namespace plisse {

/// One measured point: nominal stress [MPa] at the stretch λ of a test.
struct TestPoint {
  TestMode mode = TestMode::uniaxial;
  double stretch = 1.0;
  double stress = 0.0;  ///< nominal (force / undeformed area) [MPa], non-zero
};

struct FitSettings {
  std::string model;    ///< a registered model name
  int ogden_terms = 3;  ///< for "ogden": terms fitted (1 to 3), the others absent
};

/// The error of the fit on one test mode [relative, as fractions].
struct ModeError {
  TestMode mode = TestMode::uniaxial;
  int points = 0;
  double rms = 0.0;
  double max = 0.0;
};

/// The stretches λ of a test around 1 between which the material is stable in Drucker's sense
/// (drucker_stable), searched in [kStabilityScanMin, kStabilityScanMax] from λ = 1 outwards.
struct StabilityRange {
  TestMode mode = TestMode::uniaxial;
  double lower = 1.0;  ///< kStabilityScanMin when stable down to it
  double upper = 1.0;  ///< kStabilityScanMax when stable up to it
};
inline constexpr double kStabilityScanMin = 0.1, kStabilityScanMax = 10.0;

struct FitResult {
  std::string model;
  MaterialValues values;                  ///< every parameter of the model, fitted or fixed
  std::vector<std::string> fitted;        ///< the fitted ones, in registry order
  std::vector<ModeError> errors;          ///< per mode present in the data
  double rms = 0.0;                       ///< over all points
  std::vector<ParamViolation> broken;     ///< registry rules the fitted set breaks (then no case
                                          ///< file accepts it)
  std::vector<StabilityRange> stability;  ///< per test mode, all three
  int evaluations = 0;                    ///< residual evaluations, all starts together
};

/// The parameters a fit of `info`'s model adjusts, in registry order: all of them, or for Ogden
/// those of its first `ogden_terms` terms.
std::vector<std::string> fitted_parameters(const MaterialModelInfo& info, int ogden_terms);

/// nominal_stress, or NaN where the model is not defined (Gent past its limit).
double nominal_stress_or_nan(const AnyMaterial& material, TestMode mode, double stretch);

/// Fits `options.model` to `data`. Throws InputError (place: key "model" or "terms") for an unknown
/// model or a terms count out of range, or when no start ends with a finite model stress at every
/// data point (the report would print the penalty as the error), and Error when no start
/// converges to finite values.
FitResult fit_material(const std::vector<TestPoint>& data, const FitSettings& options);

/// Drucker's condition at the incompressible state with principal stretches λ (normalised here
/// to λ1 λ2 λ3 = 1): dτ · dε > 0 for every isochoric increment of the logarithmic strains ε_a =
/// ln λ_a, τ_a the principal Kirchhoff stresses. With ε3 = -ε1 - ε2 the pressure drops out and
/// the condition is that K_ij = ∂(τ_i - τ_3)/∂ε_j (i, j = 1, 2), the Hessian of
/// W(e^ε1, e^ε2, e^(-ε1-ε2)), be positive definite (docs/fit.md, "Stability"). K by central
/// differences of the model's stress (step 1e-4 in ε). False where the model is not defined (Gent
/// at its limit); true where its stress overflows (not judged).
bool drucker_stable(const AnyMaterial& material, const Vec3d& stretches);

/// Drucker stability along each test (see StabilityRange), in steps of 0.5 % of λ.
std::vector<StabilityRange> stability_ranges(const AnyMaterial& material);

/// `material: {model: NAME, KEY: VALUE, ...}` with 6 significant digits, the values a case needs.
std::string material_block(const FitResult& fit);

}  // namespace plisse
