#pragma once
/// The axis-aligned box around a set of points (the reference extent a check or a tolerance is
/// measured against).
#include <limits>
#include <vector>

#include "core/types.hpp"

namespace plisse {

struct BoundingBox {
  Vec3d low = Vec3d::Constant(std::numeric_limits<double>::infinity());
  Vec3d high = Vec3d::Constant(-std::numeric_limits<double>::infinity());
};

/// The componentwise smallest and largest coordinates of `points`; low = +inf and high = -inf
/// when there are none.
inline BoundingBox bounding_box(const std::vector<Vec3d>& points) {
  BoundingBox box;
  for (const Vec3d& x : points) {
    box.low = box.low.cwiseMin(x);
    box.high = box.high.cwiseMax(x);
  }
  return box;
}

}  // namespace plisse
