#pragma once
/// What defines a rigid end cap (physics/rigid_cap.hpp solves it).
#include <array>
#include <optional>
#include <string>

#include "core/error.hpp"
#include "core/types.hpp"
#include "mesh/surface_ref.hpp"
#include "physics/ramp.hpp"

namespace plisse {

/// The nodes of `surface` tied to a reference point that moves and turns rigidly
/// (docs/theory/caps.md).
struct Cap {
  std::string name;  ///< history columns `force_x:<name>`, `moment_x:<name>`, `ux:<name>`, ...
  SurfaceRef surface;
  std::optional<Vec3d> point;  ///< reference point X_c [mm]; default: mean of the nodes
  /// Prescribed displacement of X_c [mm] and rotation vector [rad] at the end of the ramp, by
  /// component; an empty one is free.
  std::array<std::optional<double>, 3> displacement, rotation;
  Vec3d force = Vec3d::Zero();   ///< [N] on the free displacement components, ramped
  Vec3d moment = Vec3d::Zero();  ///< [N mm] on the free rotation components, ramped (G6)
  Ramp ramp;
  InputPlace place;
};

}  // namespace plisse
