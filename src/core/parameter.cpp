#include "core/parameter.hpp"

#include <sstream>

namespace plisse {
namespace {
std::string number(double v) {
  std::ostringstream out;
  out.precision(12);
  out << v;
  return out.str();
}
}  // namespace

std::string Range::describe() const {
  const bool has_lower = std::isfinite(lower), has_upper = std::isfinite(upper);
  if (!has_lower && !has_upper) return "any finite value";
  if (has_lower && !has_upper) return (lower_open ? "> " : ">= ") + number(lower);
  if (!has_lower) return (upper_open ? "< " : "<= ") + number(upper);
  return std::string("in ") + (lower_open ? "(" : "[") + number(lower) + ", " + number(upper) +
         (upper_open ? ")" : "]");
}

std::optional<std::string> Range::violation(double value) const {
  if (!std::isfinite(value)) return "must be a finite number (got " + number(value) + ")";
  const bool below = lower_open ? !(value > lower) : !(value >= lower);
  const bool above = upper_open ? !(value < upper) : !(value <= upper);
  if (below || above) return "must be " + describe() + " (got " + number(value) + ")";
  return std::nullopt;
}

}  // namespace plisse
