#include "physics/die_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace plisse {

DieGeometry::DieGeometry(DieShape shape, const Vec3d& point, const Vec3d& normal, const Vec3d& axis,
                         double radius, const Vec3d& displacement, Ramp ramp)
    : shape_(shape),
      point_(point),
      normal_(normal),
      axis_(axis),
      radius_(radius),
      displacement_(displacement),
      ramp_(ramp) {
  if (shape == DieShape::plane)
    PLISSE_CHECK(std::abs(normal.norm() - 1.0) < 1e-12, "die normal must be a unit vector");
  if (shape == DieShape::cylinder)
    PLISSE_CHECK(std::abs(axis.norm() - 1.0) < 1e-12, "die axis must be a unit vector");
  if (shape != DieShape::plane)
    PLISSE_CHECK(radius > 0.0, "die radius must be > 0 (got " << radius << ")");
}

DieGap DieGeometry::gap(const Vec3d& x, double t) const {
  DieGap out;
  const Vec3d c = point(t);
  switch (shape_) {
    case DieShape::plane:
      // g = n . (x - c), n constant, H = 0   (contact.md, D2)
      out.g = normal_.dot(x - c);
      out.n = normal_;
      out.H.setZero();
      break;
    case DieShape::sphere: {
      // g = |x - c| - R, n = (x - c)/|x - c|, H = (I - n n^T)/|x - c|   (D3)
      const Vec3d r = x - c;
      const double distance = r.norm();
      PLISSE_CHECK(distance > 1e-12 * radius_, "point at the centre of a spherical die: no normal");
      out.g = distance - radius_;
      out.n = r / distance;
      out.H = (Mat3d::Identity() - out.n * out.n.transpose()) / distance;
      break;
    }
    case DieShape::cylinder: {
      // r = P (x - c) with P = I - a a^T; g = |r| - R, n = r/|r|, H = (P - n n^T)/|r|   (D4)
      const Mat3d P = Mat3d::Identity() - axis_ * axis_.transpose();
      const Vec3d r = P * (x - c);
      const double distance = r.norm();
      PLISSE_CHECK(distance > 1e-12 * radius_, "point on the axis of a cylindrical die: no normal");
      out.g = distance - radius_;
      out.n = r / distance;
      out.H = (P - out.n * out.n.transpose()) / distance;
      break;
    }
  }
  return out;
}

int DieGeometry::symmetric_planes(int mirrors) const {
  constexpr double kTol = 1e-12;
  const double scale = std::max({1.0, point_.cwiseAbs().maxCoeff(), radius_});
  int planes = 0;
  for (int k = 0; k < 3; ++k) {
    if (!(mirrors & (1 << k))) continue;
    const bool centred =
        std::abs(point_[k]) <= kTol * scale && std::abs(displacement_[k]) <= kTol * scale;
    bool symmetric = false;
    switch (shape_) {
      case DieShape::plane:
        symmetric = std::abs(normal_[k]) <= kTol;
        break;
      case DieShape::sphere:
        symmetric = centred;
        break;
      case DieShape::cylinder:
        symmetric =
            std::abs(std::abs(axis_[k]) - 1.0) <= kTol || (std::abs(axis_[k]) <= kTol && centred);
        break;
    }
    if (symmetric) planes |= 1 << k;
  }
  return planes;
}

}  // namespace plisse
