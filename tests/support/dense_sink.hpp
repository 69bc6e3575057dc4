#pragma once
/// A TangentSink that collects a model term's tangent into a dense matrix over the full state,
/// for finite-difference checks of small problems.
#include <Eigen/Dense>
#include <span>

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

}  // namespace plisse::test
