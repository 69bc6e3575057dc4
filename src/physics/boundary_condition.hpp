#pragma once
/// The settings of the `boundary:` section's conditions, as a case gives them
/// (physics/dirichlet.hpp turns them into constrained components; src/terms has their kinds).
#include <array>
#include <optional>
#include <string>

#include "core/error.hpp"
#include "core/types.hpp"
#include "mesh/surface_ref.hpp"
#include "physics/ramp.hpp"

namespace plisse {

/// A condition on the nodes of a tagged surface that prescribes no value: `fixed` (u = 0) or
/// `symmetry` (zero displacement normal to the surface's plane).
struct SurfaceConditionSettings {
  std::string name;  ///< optional, unique; the reaction force on the surface is reported in the
                     ///< history as `force_x:<name>`, `force_y:<name>`, `force_z:<name>`
  SurfaceRef surface;
  InputPlace place;
};

/// A `clamped` or `hinged` condition on an edge of a shell: its nodes moved together by `value`
/// (a grip; zero holds the edge), the slope across the edge held (clamped) or free (hinged).
struct ShellEdgeConditionSettings {
  std::string name;  ///< as SurfaceConditionSettings::name
  SurfaceRef surface;
  Vec3d value = Vec3d::Zero();  ///< displacement of the edge at the end of the ramp [mm]
  Ramp ramp;
  InputPlace place;
};

/// A `displacement` condition: prescribed components on the nodes of a tagged surface.
struct DisplacementConditionSettings {
  std::string name;  ///< as SurfaceConditionSettings::name
  SurfaceRef surface;
  /// Prescribed components [mm] at the end of the ramp; an empty optional (`~`/null in YAML)
  /// leaves that component free.
  std::array<std::optional<double>, 3> value{};
  Ramp ramp;
  InputPlace place;
};

}  // namespace plisse
