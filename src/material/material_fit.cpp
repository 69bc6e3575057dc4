#include "material/material_fit.hpp"

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>
#include <variant>

#include "core/error.hpp"
#include "material/inadmissible_deformation.hpp"

namespace plisse {
namespace {

/// A residual for a point where the model is not defined (Gent past its limit) or not finite: a
/// large value the minimiser moves away from.
constexpr double kPenalty = 1e3;

/// Small-strain shear modulus estimated from the data: the median over the points with
/// 0.8 <= λ <= 1.5 (all points if none) of t / g(λ), g the neo-Hookean shape of the mode
/// (uniaxial λ - λ^-2, equibiaxial λ - λ^-5, planar λ - λ^-3).
double small_strain_modulus(const std::vector<TestPoint>& data) {
  std::vector<double> near, all;
  for (const TestPoint& p : data) {
    const double l = p.stretch;
    const double g = p.mode == TestMode::uniaxial      ? l - std::pow(l, -2)
                     : p.mode == TestMode::equibiaxial ? l - std::pow(l, -5)
                                                       : l - std::pow(l, -3);
    if (g == 0.0) continue;
    const double mu = p.stress / g;
    if (!(mu > 0.0) || !std::isfinite(mu)) continue;
    all.push_back(mu);
    if (l >= 0.8 && l <= 1.5) near.push_back(mu);
  }
  std::vector<double>& use = near.empty() ? all : near;
  if (use.empty()) return 1.0;
  std::nth_element(use.begin(), use.begin() + use.size() / 2, use.end());
  return use[use.size() / 2];
}

/// Starting points: each gives the fitted parameters' values (in `fitted` order) and its model
/// starts from there. Derived from the small-strain modulus mu and the data's largest Ī1 - 3.
std::vector<std::vector<double>> starts(const std::string& model, int terms, double mu,
                                        double max_I1_minus_3, double max_stretch) {
  if (model == "neo-hookean") return {{mu / 2}};
  if (model == "mooney-rivlin") return {{0.4 * mu, 0.1 * mu}, {0.5 * mu, 0.0}};
  if (model == "fung") return {{mu, 0.1}, {mu, 0.01}};
  if (model == "yeoh") return {{mu / 2, 0.0, 0.0}, {mu / 2, -0.01 * mu, 0.001 * mu}};
  if (model == "gent") return {{mu, std::max(2.0 * max_I1_minus_3, 10.0)}};
  if (model == "arruda-boyce") return {{mu, std::max(1.5 * max_stretch, 2.0)}};
  // Ogden: each term's exponent from a few rubber-like sets; the shear modulus either shared
  // equally (μ_p α_p / 2 = mu / N) or carried by the first term with 1 % in each other.
  const std::vector<std::vector<double>> alphas =
      terms == 1 ? std::vector<std::vector<double>>{{2.0}, {1.3}, {3.0}}
      : terms == 2
          ? std::vector<std::vector<double>>{{2.0, -2.0}, {1.3, 5.0}, {3.0, -1.0}}
          : std::vector<std::vector<double>>{{1.3, 5.0, -2.0}, {2.0, 4.0, -2.0}, {1.0, 3.0, -1.0}};
  std::vector<std::vector<double>> out;
  for (const auto& a : alphas) {
    for (const bool equal_shares : {true, false}) {
      std::vector<double> x;
      for (int p = 0; p < terms; ++p) {
        const double share =
            equal_shares ? 1.0 / terms : (p == 0 ? 1.0 - 0.01 * (terms - 1) : 0.01);
        x.push_back(2.0 * mu * share / a[p]);  // μ_p with μ_p α_p / 2 = share mu
        x.push_back(a[p]);
      }
      out.push_back(x);
    }
  }
  return out;
}

/// The model with `x` in the fitted parameters and the others at their defaults (0 for Ogden's
/// absent terms). No rule is checked: the minimiser may pass through sets the registry refuses.
AnyMaterial build(const MaterialModelInfo& info, const std::vector<std::string>& fitted,
                  const Eigen::VectorXd& x, MaterialValues* values = nullptr) {
  MaterialValues v;
  for (const ParamSpec& p : info.params) v[p.name] = p.default_value.value_or(0.0);
  for (std::size_t k = 0; k < fitted.size(); ++k) v[fitted[k]] = x(static_cast<Eigen::Index>(k));
  if (values != nullptr) *values = v;
  return info.make(v);
}

/// The relative residuals of all points for the fitted parameters x (Eigen's functor interface).
struct Residuals {
  using Scalar = double;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;

  const MaterialModelInfo* info;
  const std::vector<std::string>* fitted;
  const std::vector<TestPoint>* data;
  int* evaluations;

  int inputs() const { return static_cast<int>(fitted->size()); }
  int values() const { return static_cast<int>(data->size()); }
  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& r) const {
    ++*evaluations;
    const AnyMaterial m = build(*info, *fitted, x);
    for (std::size_t i = 0; i < data->size(); ++i) {
      const TestPoint& p = (*data)[i];
      const double e = (nominal_stress_or_nan(m, p.mode, p.stretch) - p.stress) / p.stress;
      r(static_cast<Eigen::Index>(i)) = std::isfinite(e) ? e : kPenalty;
    }
    return 0;
  }
};

}  // namespace

std::vector<std::string> fitted_parameters(const MaterialModelInfo& info, int ogden_terms) {
  std::vector<std::string> names;
  for (const ParamSpec& p : info.params) {
    if (info.name == "ogden") {
      const int term = p.name.back() - '0';
      if (term > ogden_terms) continue;
    }
    names.push_back(p.name);
  }
  return names;
}

double nominal_stress_or_nan(const AnyMaterial& material, TestMode mode, double stretch) {
  try {
    return nominal_stress(material, mode, stretch);
  } catch (const InadmissibleDeformation&) {
    return std::numeric_limits<double>::quiet_NaN();
  }
}

FitResult fit_material(const std::vector<TestPoint>& data, const FitSettings& options) {
  const MaterialModelInfo* info = find_material_model(options.model);
  if (info == nullptr) {
    std::string known;
    for (const auto& m : material_models()) known += (known.empty() ? "" : ", ") + m.name;
    throw InputError({"command line", 0, 0, "model"},
                     "unknown material model '" + options.model + "' (known: " + known + ")");
  }
  if (!info->isotropic)
    throw InputError({"command line", 0, 0, "model"},
                     "'" + info->name +
                         "' is not isotropic: the uniaxial, equibiaxial and planar "
                         "tests do not determine its fibres; fit an isotropic model");
  if (info->name == "ogden" && (options.ogden_terms < 1 || options.ogden_terms > 3))
    throw InputError(
        {"command line", 0, 0, "terms"},
        "an Ogden fit has 1 to 3 terms (got " + std::to_string(options.ogden_terms) + ")");
  PLISSE_CHECK(!data.empty(), "fit_material: no data");
  const std::vector<std::string> fitted = fitted_parameters(*info, options.ogden_terms);
  PLISSE_CHECK(data.size() >= fitted.size(),
               "fit_material: " << data.size() << " points for " << fitted.size() << " parameters");

  double max_I1 = 0.0, max_stretch = 1.0;
  for (const TestPoint& p : data) {
    const Mat3d F = test_deformation(p.mode, p.stretch);
    max_I1 = std::max(max_I1, F.squaredNorm() - 3.0);
    max_stretch = std::max({max_stretch, p.stretch, 1.0 / p.stretch});
  }
  const double mu = small_strain_modulus(data);

  FitResult result;
  result.model = info->name;
  result.fitted = fitted;
  int evaluations = 0;
  Residuals f{info, &fitted, &data, &evaluations};
  double best = std::numeric_limits<double>::infinity();
  Eigen::VectorXd best_x;
  std::size_t fewest_non_finite = data.size() + 1;  // of the starts refused for non-finite stress
  for (const std::vector<double>& start :
       starts(info->name, options.ogden_terms, mu, max_I1, max_stretch)) {
    Eigen::VectorXd x =
        Eigen::Map<const Eigen::VectorXd>(start.data(), static_cast<Eigen::Index>(start.size()));
    Eigen::NumericalDiff<Residuals> df(f);
    Eigen::LevenbergMarquardt<Eigen::NumericalDiff<Residuals>> lm(df);
    lm.parameters.maxfev = 4000;
    lm.parameters.xtol = 1e-12;
    lm.parameters.ftol = 1e-14;
    lm.minimize(x);
    Eigen::VectorXd r(static_cast<Eigen::Index>(data.size()));
    f(x, r);
    const double sum = r.squaredNorm();
    if (!std::isfinite(sum) || !x.allFinite() || !(sum < best)) continue;
    // A point where the model's stress is not a finite number has only the penalty as its
    // residual: such parameters do not fit the data, however small the sum.
    const AnyMaterial m = build(*info, fitted, x);
    std::size_t n_non_finite = 0;
    for (const TestPoint& p : data)
      if (!std::isfinite(nominal_stress_or_nan(m, p.mode, p.stretch))) ++n_non_finite;
    if (n_non_finite > 0) {
      fewest_non_finite = std::min(fewest_non_finite, n_non_finite);
      continue;
    }
    best = sum;
    best_x = x;
  }
  if (!std::isfinite(best) && fewest_non_finite < data.size() + 1)
    throw InputError({"command line", 0, 0, "model"},
                     "no fit of '" + info->name +
                         "' gives a finite stress at every data point (the best leaves " +
                         std::to_string(fewest_non_finite) + " of " + std::to_string(data.size()) +
                         " points without one: stresses beyond double precision, or stretches "
                         "past the model's limit); these data are out of the model's reach, "
                         "check their units or fit another model");
  if (!std::isfinite(best))
    throw Error("plisse fit: no start of the minimiser reached finite parameters for '" +
                info->name + "'");
  const AnyMaterial m = build(*info, fitted, best_x, &result.values);
  result.evaluations = evaluations;

  Eigen::VectorXd r(static_cast<Eigen::Index>(data.size()));
  f(best_x, r);
  --result.evaluations;  // the last two evaluations were for the report
  result.rms = std::sqrt(r.squaredNorm() / static_cast<double>(data.size()));
  for (const TestMode mode : {TestMode::uniaxial, TestMode::equibiaxial, TestMode::planar}) {
    ModeError e;
    e.mode = mode;
    double sum = 0.0;
    for (std::size_t i = 0; i < data.size(); ++i) {
      if (data[i].mode != mode) continue;
      const double ri = r(static_cast<Eigen::Index>(i));
      ++e.points;
      sum += ri * ri;
      e.max = std::max(e.max, std::abs(ri));
    }
    if (e.points == 0) continue;
    e.rms = std::sqrt(sum / e.points);
    result.errors.push_back(e);
  }
  result.broken = validate_material(info->name, result.values);
  result.stability = stability_ranges(m);
  return result;
}

bool drucker_stable(const AnyMaterial& material, const Vec3d& stretches) {
  const double J = stretches.prod();
  if (!(J > 0.0)) return false;
  const Vec3d eps = (stretches / std::cbrt(J)).array().log();
  // g_i = τ_i - τ_3 at ε1, ε2 (ε3 = -ε1 - ε2): the isochoric Kirchhoff stress σ̄ = P Fᵀ at J = 1.
  const auto g = [&](double e1, double e2) {
    const Mat3d F = Vec3d(std::exp(e1), std::exp(e2), std::exp(-e1 - e2)).asDiagonal();
    const Mat3d P = std::visit([&](const auto& m) { return m.evaluate(F).P; }, material);
    const Mat3d tau = P * F.transpose();
    return Eigen::Vector2d(tau(0, 0) - tau(2, 2), tau(1, 1) - tau(2, 2));
  };
  const double h = 1e-4;
  Eigen::Matrix2d K;
  try {
    K.col(0) = (g(eps(0) + h, eps(1)) - g(eps(0) - h, eps(1))) / (2 * h);
    K.col(1) = (g(eps(0), eps(1) + h) - g(eps(0), eps(1) - h)) / (2 * h);
  } catch (const InadmissibleDeformation&) {
    return false;
  }
  // A stress that overflows (Fung's exponential at a thickness stretch near 100) cannot be judged:
  // not counted as an instability.
  if (!K.allFinite()) return true;
  // Scaled to entries of order 1 first: an exponential model's K can reach 1e150, whose
  // determinant would overflow.
  const double scale = K.cwiseAbs().maxCoeff();
  if (!(scale > 0.0)) return false;
  const Eigen::Matrix2d S = 0.5 * (K + K.transpose()) / scale;
  return S(0, 0) > 0.0 && S.determinant() > 0.0;
}

std::vector<StabilityRange> stability_ranges(const AnyMaterial& material) {
  std::vector<StabilityRange> out;
  for (const TestMode mode : {TestMode::uniaxial, TestMode::equibiaxial, TestMode::planar}) {
    const auto stable = [&](double l) {
      return drucker_stable(material, test_deformation(mode, l).diagonal());
    };
    StabilityRange s;
    s.mode = mode;
    s.upper = kStabilityScanMax;
    for (double l = 1.0; l <= kStabilityScanMax; l *= 1.005) {
      if (!stable(l)) {
        s.upper = l;
        break;
      }
    }
    s.lower = kStabilityScanMin;
    for (double l = 1.0; l >= kStabilityScanMin; l /= 1.005) {
      if (!stable(l)) {
        s.lower = l;
        break;
      }
    }
    out.push_back(s);
  }
  return out;
}

std::string material_block(const FitResult& fit) {
  std::ostringstream out;
  out.precision(6);
  out << "material: {model: " << fit.model;
  const MaterialModelInfo* info = find_material_model(fit.model);
  PLISSE_CHECK(info != nullptr, "material_block: unknown model " << fit.model);
  for (const ParamSpec& p : info->params) {
    const double v = fit.values.at(p.name);
    // Leave out optional parameters at their defaults (Ogden's absent terms).
    if (p.default_value && v == *p.default_value &&
        std::find(fit.fitted.begin(), fit.fitted.end(), p.name) == fit.fitted.end())
      continue;
    out << ", " << p.name << ": " << v;
  }
  out << "}";
  return out.str();
}

}  // namespace plisse
