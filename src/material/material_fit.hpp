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

struct FitOptions {
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

/// The stretches around 1 between which the nominal stress of a test rises with the stretch
/// (Drucker's condition along that test's path), searched in [kStabilityScanMin,
/// kStabilityScanMax].
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

/// Fits `options.model` to `data`. Throws InputError (place: key "model" or "terms") for an unknown
/// model or a terms count out of range, and Error when no start converges to finite values.
FitResult fit_material(const std::vector<TestPoint>& data, const FitOptions& options);

/// Drucker's condition along each test path for a given material (see StabilityRange).
std::vector<StabilityRange> stability_ranges(const AnyMaterial& material);

/// `material: {model: NAME, KEY: VALUE, ...}` with 6 significant digits, the values a case needs.
std::string material_block(const FitResult& fit);

}  // namespace plisse
