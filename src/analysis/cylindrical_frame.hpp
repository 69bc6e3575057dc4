#pragma once
/// Cylindrical frame about a wrinkle axis (docs/theory/wrinkles.md, section 1).
#include <cmath>

#include "core/types.hpp"

namespace plisse {

/// Point coordinates in a cylindrical frame: height h, radius rho, azimuth theta, latitude phi.
struct CylindricalCoordinates {
  double h = 0.0;      ///< (X - c) . a [mm]                              (wrinkles.md, W1)
  double rho = 0.0;    ///< |(X - c) - h a| [mm]                          (W1)
  double theta = 0.0;  ///< azimuth in (-pi, pi] [rad]                     (W2)
  double phi = 0.0;    ///< latitude atan2(h, rho) in [-pi/2, pi/2] [rad]  (W3)
};

/// Frame about the coordinate axis `axis` (0 x, 1 y, 2 z) through `center`, with the cyclic
/// in-plane basis (e1, e2): axis x -> (y, z), y -> (z, x), z -> (x, y), so that (e1, e2, a) is
/// right-handed and theta grows from e1 towards e2.
class CylindricalFrame {
 public:
  /// Throws Error (PLISSE_CHECK) unless 0 <= axis <= 2.
  CylindricalFrame(int axis, const Vec3d& center);

  CylindricalCoordinates coordinates(const Vec3d& X) const {
    const Vec3d q = X - center_;
    CylindricalCoordinates c;
    c.h = q[axis_];
    const double q1 = q[first_], q2 = q[second_];
    c.rho = std::hypot(q1, q2);
    c.theta = std::atan2(q2, q1);
    c.phi = std::atan2(c.h, c.rho);
    return c;
  }
  /// Unit radial direction e_rho(theta) = cos(theta) e1 + sin(theta) e2.
  Vec3d radial(double theta) const {
    Vec3d e = Vec3d::Zero();
    e[first_] = std::cos(theta);
    e[second_] = std::sin(theta);
    return e;
  }
  /// Unit axis direction a.
  Vec3d axis_direction() const { return Vec3d::Unit(axis_); }
  /// Signed distance-like function of the cone phi = phi0 (wrinkles.md, W4):
  ///   f(X) = h cos(phi0) - rho sin(phi0) = r sin(phi - phi0),  r = |X - c|,
  /// zero on the cone, positive above it (towards +a).
  double cone_function(const Vec3d& X, double phi0) const {
    const CylindricalCoordinates c = coordinates(X);
    return c.h * std::cos(phi0) - c.rho * std::sin(phi0);
  }
  int axis() const { return axis_; }
  const Vec3d& center() const { return center_; }

 private:
  int axis_;
  int first_;   ///< index of e1
  int second_;  ///< index of e2
  Vec3d center_;
};

}  // namespace plisse
