#pragma once
/// Helpers for finite-difference checks of model terms on small problems: a TangentSink that
/// collects the tangent into a dense matrix over the full state, random states, the residual alone.
#include <Eigen/Dense>
#include <algorithm>
#include <random>
#include <span>
#include <vector>

#include "physics/model_term.hpp"

namespace plisse::test {

class DenseSink : public TangentSink {
 public:
  explicit DenseSink(int n) : K(Eigen::MatrixXd::Zero(n, n)) {}
  void add(std::span<const int> rows, std::span<const int> cols,
           std::span<const double> values) override {
    for (size_t i = 0; i < rows.size(); ++i)
      for (size_t j = 0; j < cols.size(); ++j) K(rows[i], cols[j]) += values[i * cols.size() + j];
  }
  Eigen::MatrixXd K;
};

/// n values uniform in [-scale, scale], reproducible from `seed`.
inline std::vector<double> random_state(int n, unsigned seed, double scale) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-scale, scale);
  std::vector<double> x(n);
  for (double& v : x) v = u(rng);
  return x;
}

/// The residual of `term` alone at (t, x).
inline Eigen::VectorXd term_residual(ModelTerm& term, double t, const std::vector<double>& x) {
  std::vector<double> r(x.size(), 0.0);
  term.assemble(t, x, r, nullptr);
  return Eigen::Map<Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size()));
}

/// Largest |central difference of the residual - K| over the columns of K (step h; pressure
/// columns skipped when `skip_pressures`, for terms that do not depend on them).
inline double max_tangent_error(ModelTerm& term, double t, const std::vector<double>& x,
                                const Eigen::MatrixXd& K, double h, bool skip_pressures = false) {
  double max_error = 0.0;
  for (int j = 0; j < static_cast<int>(x.size()); ++j) {
    if (skip_pressures && j % kValuesPerNode == 3) continue;
    auto xp = x, xm = x;
    xp[j] += h;
    xm[j] -= h;
    const Eigen::VectorXd fd = (term_residual(term, t, xp) - term_residual(term, t, xm)) / (2 * h);
    max_error = std::max(max_error, (fd - K.col(j)).cwiseAbs().maxCoeff());
  }
  return max_error;
}

}  // namespace plisse::test
