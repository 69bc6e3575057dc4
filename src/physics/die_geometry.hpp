#pragma once
/// The surface of a rigid analytic die (plane, sphere, cylinder) translated by a prescribed, ramped
/// displacement, and the signed gap of a point to it (docs/theory/contact.md, D1-D4).
#include "core/types.hpp"
#include "physics/ramp.hpp"

namespace plisse {

enum class DieShape { plane, sphere, cylinder };

/// Gap of one point x to the die at time t:
///   g [mm], positive when x is separated from the die, negative when it penetrates;
///   n = dg/dx, the unit normal of the die surface at the closest point, pointing towards the body;
///   H = dn/dx = d^2 g/dx^2 [1/mm], symmetric (zero for a plane).
struct DieGap {
  double g = 0.0;
  Vec3d n = Vec3d::UnitY();
  Mat3d H = Mat3d::Zero();
};

class DieGeometry {
 public:
  /// plane: `point` on the plane, unit `normal` pointing towards the body (the body is on the side
  /// n . (x - point) > 0). sphere: centre `point`, `radius`, body outside. cylinder: `point` on the
  /// axis, unit `axis`, `radius`, body outside. The die translates by ramp.factor(t) *
  /// `displacement` [mm] (D1). Throws plisse::Error for a non-unit direction or radius <= 0.
  DieGeometry(DieShape shape, const Vec3d& point, const Vec3d& normal, const Vec3d& axis,
              double radius, const Vec3d& displacement, Ramp ramp);

  DieShape shape() const { return shape_; }
  /// The translation of the die at time t [mm] (D1).
  Vec3d translation(double t) const { return ramp_.factor(t) * displacement_; }
  /// The reference point (plane point, sphere centre, point on the axis) at time t [mm].
  Vec3d point(double t) const { return point_ + translation(t); }

  /// Gap, normal and normal derivative of the point x [mm] at time t (D2-D4). Throws plisse::Error
  /// when x lies on the centre (sphere) or the axis (cylinder), where the normal is undefined.
  DieGap gap(const Vec3d& x, double t) const;

  /// The planes among `mirrors` (bit k: x_k = 0) whose reflection maps the die onto itself at every
  /// t: a plane die whose normal lies in the plane; a sphere centred on it that moves in it; a
  /// cylinder whose axis crosses it at a right angle, or lies in it and moves in it. Its whole-body
  /// force sums its images (whole_body_force, physics/dirichlet.hpp); any other mirror image of
  /// the die is another die.
  int symmetric_planes(int mirrors) const;

 private:
  DieShape shape_;
  Vec3d point_, normal_, axis_;
  double radius_;
  Vec3d displacement_;
  Ramp ramp_;
};

}  // namespace plisse
