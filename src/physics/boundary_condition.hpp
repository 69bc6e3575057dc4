#pragma once
/// A Dirichlet condition on the nodes of a tagged surface, as a case gives it
/// (physics/dirichlet.hpp turns it into constrained components).
#include <array>
#include <optional>
#include <string>

#include "core/error.hpp"
#include "mesh/surface_ref.hpp"
#include "physics/ramp.hpp"

namespace plisse {

enum class BoundaryType { fixed, symmetry, displacement };

/// Dirichlet condition on the nodes of a tagged surface.
struct BoundaryCondition {
  BoundaryType type = BoundaryType::fixed;
  std::string name;  ///< optional, unique; the reaction force on the surface is reported in the
                     ///< history as `force_x:<name>`, `force_y:<name>`, `force_z:<name>`
  SurfaceRef surface;
  /// `displacement` only: prescribed components [mm] at the end of the ramp; an empty optional
  /// (`~`/null in YAML) leaves that component free.
  std::array<std::optional<double>, 3> value{};
  Ramp ramp;
  InputPlace place;
};

}  // namespace plisse
