#include "analysis/cylindrical_frame.hpp"

#include "core/error.hpp"

namespace plisse {

CylindricalFrame::CylindricalFrame(int axis, const Vec3d& center)
    : axis_(axis), first_((axis + 1) % 3), second_((axis + 2) % 3), center_(center) {
  PLISSE_CHECK(axis >= 0 && axis <= 2, "wrinkle axis must be 0 (x), 1 (y) or 2 (z), got " << axis);
  PLISSE_CHECK(center.allFinite(), "wrinkle axis centre must be finite");
}

}  // namespace plisse
