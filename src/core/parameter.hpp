#pragma once
/// Declared parameters: name, admissible range, unit and help, in one place (docs/architecture.md,
/// "Coding conventions"). The same table validates input, produces error messages and generates
/// documentation.
#include <cmath>
#include <limits>
#include <optional>
#include <string>

namespace plisse {

/// An admissible interval for a real parameter. Bounds may be open or closed; values must be
/// finite.
struct Range {
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  bool lower_open = true;
  bool upper_open = true;

  static Range any() { return {}; }
  static Range positive() { return {0.0, std::numeric_limits<double>::infinity(), true, true}; }
  static Range non_negative() {
    return {0.0, std::numeric_limits<double>::infinity(), false, true};
  }
  static Range closed(double lo, double hi) { return {lo, hi, false, false}; }
  static Range at_least(double lo) {
    return {lo, std::numeric_limits<double>::infinity(), false, true};
  }

  /// Empty when `value` is admissible, otherwise the rule broken, e.g. "must be > 0 (got -1)".
  std::optional<std::string> violation(double value) const;
  /// The rule in words, e.g. "> 0", "in [1, 100]", "any finite value".
  std::string describe() const;
};

/// One declared real parameter.
struct ParamSpec {
  std::string name;  ///< input key, snake_case
  Range range;
  std::string unit;  ///< e.g. "MPa", "mm", "-" for dimensionless
  std::string help;
  std::optional<double> default_value;  ///< empty: required
};

}  // namespace plisse
