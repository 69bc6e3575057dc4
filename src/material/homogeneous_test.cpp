#include "material/homogeneous_test.hpp"

#include <cmath>
#include <variant>

namespace plisse {

std::string test_mode_name(TestMode mode) {
  switch (mode) {
    case TestMode::uniaxial:
      return "uniaxial";
    case TestMode::equibiaxial:
      return "equibiaxial";
    case TestMode::planar:
      return "planar";
  }
  return "?";
}

std::optional<TestMode> parse_test_mode(const std::string& name) {
  if (name == "uniaxial") return TestMode::uniaxial;
  if (name == "equibiaxial" || name == "biaxial") return TestMode::equibiaxial;
  if (name == "planar" || name == "pure-shear" || name == "pure_shear") return TestMode::planar;
  return std::nullopt;
}

Mat3d test_deformation(TestMode mode, double stretch) {
  const double l = stretch;
  switch (mode) {
    case TestMode::uniaxial:
      return Vec3d(l, 1.0 / std::sqrt(l), 1.0 / std::sqrt(l)).asDiagonal();
    case TestMode::equibiaxial:
      return Vec3d(l, l, 1.0 / (l * l)).asDiagonal();
    case TestMode::planar:
      return Vec3d(l, 1.0, 1.0 / l).asDiagonal();
  }
  return Mat3d::Identity();
}

double nominal_stress(const AnyMaterial& material, TestMode mode, double stretch) {
  const Mat3d F = test_deformation(mode, stretch);
  const Mat3d P = std::visit([&](const auto& m) { return m.evaluate(F).P; }, material);
  const Mat3d sigma = P * F.transpose();  // J = 1
  const int free = mode == TestMode::uniaxial ? 1 : 2;
  return (sigma(0, 0) - sigma(free, free)) / stretch;
}

}  // namespace plisse
